// Burner caps as category evidence. The category classifier reads an object's shape as a whole,
// and a range whose hob sits in a raised rim (a tray around its grate) looks like a basin to it: a
// real propane range was filed as a sink with probability 0.79. Its burner caps are a family of
// three or more equal round flat parts, each a sizeable share of the object across; sinks have one
// drain per basin and taps' knobs that are a few centimetres on a counter or vanity. A sink
// decision on a mesh with such a family is turned into a stove decision, which the evidence gate
// then checks with the stove models like any other (core/annotate/category_evidence.h).
#pragma once

#include <functional>

#include "core/annotate/category_classifier.h"

namespace sagrid {

struct Mesh;

struct BurnerCapRule {
  int minCaps = 3;  // equal round flat parts in the family
  // Each cap at least this share of the mesh's largest extent across (the real sinks' round
  // knobs: at most 0.038; real ranges' caps: 0.066 to 0.15).
  float minDiameterShare = 0.05f;
};

// Whether `mesh` (z-up mesh frame) has a family of at least rule.minCaps congruent round flat
// parts (isRoundFlatPart; congruentParts within kCopyTolerance; kMinInstanceTriangles or more
// each) of box width at least rule.minDiameterShare of its largest extent.
bool hasBurnerCaps(const Mesh& mesh, const BurnerCapRule& rule = {});

// `decision` unchanged unless it files the object under "sink"; then, when the mesh (read only
// then) has burner caps, the same decision with category and best "stove" and byBurnerCaps set.
CategoryDecision withBurnerCaps(const CategoryDecision& decision, const std::function<Mesh()>& mesh,
                                const BurnerCapRule& rule = {});

}  // namespace sagrid
