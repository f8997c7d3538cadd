// Leave-one-source-out evaluation of the units guess with the size memory
// (core/annotate/size_memory.h), and the choice of how it recalls: every curated object's units
// guessed as `annotate` would (its decided category, its file's sizes, its descriptor) with a
// memory that holds no object of its source, scored against its curated units; the measures the
// memory may recall, how many objects and its far factor are chosen for each source on the other
// sources alone.
// `sagrid units memory` prints it.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/annotate/size_memory.h"
#include "core/common/paired_change.h"

namespace sagrid {

struct UnitsCase {
  RememberedSize object;  // its extent in file units, curated units and size in metres
  std::string group;      // the dataset folder it was read from (or "memory"), for the report
};

struct UnitsScore {
  std::size_t objects = 0, right = 0, notMetres = 0, notMetresRight = 0;
};

// One way of recalling sizes: the measures a memory may recall, how many curated objects it
// recalls, and its far factor (infinity: no memory, the named units alone).
struct MemoryRecall {
  std::vector<SizeMeasure> measures;
  double farFactor = std::numeric_limits<double>::infinity();
  int neighbours = 5;
  bool namedUnitsOnly() const { return !(farFactor < std::numeric_limits<double>::infinity()); }
};
// What `sagrid units memory` and the GUI's Train panel judge unless told otherwise: each measure
// alone and the most agreed of all three, recalling 1, 3, 5 or 9 objects, at far factors 1.5, 2,
// 3, 4, 5 and 8.
std::vector<std::vector<SizeMeasure>> defaultMeasureSets();
std::vector<int> defaultNeighbourCounts();
std::vector<double> defaultFarFactors();

// Each set of measures with each number of objects recalled and each factor, then the named units
// alone (last).
std::vector<MemoryRecall> recallCandidates(const std::vector<std::vector<SizeMeasure>>& measureSets,
                                           const std::vector<int>& neighbourCounts,
                                           const std::vector<double>& factors);
// "memory (largest extent, 5 nearest), far factor 4", "memory (most agreed of largest extent,
// height, 5 nearest), ...", "named units only (no memory)".
std::string recallName(const MemoryRecall& recall);

struct UnitsLosoReport {
  std::vector<MemoryRecall> candidates;
  std::vector<std::vector<UnitsScore>> byCandidate;    // [candidate][group], the last group all
  std::vector<UnitsScore> chosenLeavingSourceOut;      // [group], the last all
  std::vector<std::string> groups;                     // without "all"
  std::vector<std::pair<std::string, std::size_t>> chosenBySource;  // source -> candidate
  std::vector<std::string> wrongChosen;  // "id (source): guessed X, curated Y" with the chosen recall
  // Per object, 1 where its guess is wrong: with the named units alone (current) and with the
  // recall chosen leaving its source out (candidate); what the memory's guard pairs.
  std::vector<ObjectFigures> namedAgainstChosen;
  std::size_t chosenOnAll = 0;           // the candidate the shipped memory keeps
  double tolerance = 1.5;
};

// The objects a memory holds as cases (group "memory"), so that a memory grows with newly curated
// objects without the datasets it was built from.
std::vector<UnitsCase> casesOfMemory(const SizeMemory& memory);
// `earlier` and then `more`, an object of `more` replacing the one of `earlier` with its id and
// source (curated again).
std::vector<UnitsCase> mergeCases(std::vector<UnitsCase> earlier, const std::vector<UnitsCase>& more);

// Right: the guess within `tolerance` of the curated units; not in metres: the curated units
// more than `tolerance` from 1. For each source, the candidate with the most right on the other
// sources (ties: the larger factor, then the earlier candidate).
UnitsLosoReport evaluateSizeMemory(const std::vector<UnitsCase>& cases,
                                   const std::vector<MemoryRecall>& candidates,
                                   const std::string& featureConfigHash, double tolerance = 1.5);

std::string unitsLosoMarkdown(const UnitsLosoReport& report);

}  // namespace sagrid
