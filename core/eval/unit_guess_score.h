// How often the units guess (core/mesh/unit_guess.h) recorded by `annotate` agrees with the
// curated units: an object's guess is right when it lies within `factor` of the curated
// meters_per_unit, and its file counts as not in metres when the curated scale is off 1 by more
// than `factor` (issue 41's target is on those files). `sagrid eval --units PRED --truth DIR`.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/labels/labels.h"

namespace sagrid {

struct UnitGuessScore {
  std::size_t objects = 0, right = 0;
  std::size_t notMetres = 0, notMetresRight = 0;
  std::size_t declared = 0;  // units the object's source declared (annotate recorded no guess)
  std::vector<std::string> wrong;  // "id: guessed X, curated Y"
};

// Pairs of (annotate's labels with object.meters_per_unit_guess or declared units, curated labels).
UnitGuessScore scoreUnitGuesses(const std::vector<std::pair<ObjectLabels, ObjectLabels>>& predictedAndCurated,
                                double factor = 1.5);

std::string unitGuessMarkdown(const UnitGuessScore& score, double factor = 1.5);

}  // namespace sagrid
