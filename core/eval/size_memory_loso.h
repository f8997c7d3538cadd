// Leave-one-source-out evaluation of the units guess with the size memory
// (core/annotate/size_memory.h), and the choice of its far factor: every curated object's units
// guessed as `annotate` would (its decided category, its file's largest extent, its descriptor)
// with a memory that holds no object of its source, scored against its curated units; the factor
// is chosen for each source on the other sources alone. `sagrid units memory` prints it.
#pragma once

#include <string>
#include <vector>

#include "core/annotate/size_memory.h"

namespace sagrid {

struct UnitsCase {
  RememberedSize object;  // its extent in file units, curated units and size in metres
  std::string group;      // the dataset folder it was read from (or "memory"), for the report
};

struct UnitsScore {
  std::size_t objects = 0, right = 0, notMetres = 0, notMetresRight = 0;
};

struct UnitsLosoReport {
  std::vector<double> factors;                         // candidates; infinity = named units only
  std::vector<std::vector<UnitsScore>> byFactor;       // [factor][group], the last group all
  std::vector<UnitsScore> chosenLeavingSourceOut;      // [group], the last all
  std::vector<std::string> groups;                     // without "all"
  std::vector<std::pair<std::string, double>> chosenBySource;
  std::vector<std::string> wrongChosen;  // "id (source): guessed X, curated Y" with the chosen factor
  double chosenOnAll = 0;                              // the factor the shipped memory keeps
  double tolerance = 1.5;
};

// The objects a memory holds as cases (group "memory"), so that a memory grows with newly curated
// objects without the datasets it was built from.
std::vector<UnitsCase> casesOfMemory(const SizeMemory& memory);
// `earlier` and then `more`, an object of `more` replacing the one of `earlier` with its id and
// source (curated again).
std::vector<UnitsCase> mergeCases(std::vector<UnitsCase> earlier, const std::vector<UnitsCase>& more);

// Right: the guess within `tolerance` of the curated units; not in metres: the curated units
// more than `tolerance` from 1. `neighbours`: how many curated objects the memory recalls.
UnitsLosoReport evaluateSizeMemory(const std::vector<UnitsCase>& cases,
                                   const std::vector<double>& factors,
                                   const std::string& featureConfigHash, int neighbours = 5,
                                   double tolerance = 1.5);

std::string unitsLosoMarkdown(const UnitsLosoReport& report);

}  // namespace sagrid
