// Burner caps as category evidence. The category classifier reads an object's shape as a whole,
// and a range whose hob sits in a raised rim (a tray around its grate) looks like a basin to it: a
// real propane range was filed as a sink with probability 0.79. Its burner caps are a family of
// three or more equal round flat parts, each a sizeable share of the object across; sinks have one
// drain per basin and taps' knobs that are a few centimetres on a counter or vanity. A sink
// decision on a mesh with such a family is turned into a stove decision, which the evidence gate
// then checks with the stove models like any other (core/annotate/category_evidence.h).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "core/annotate/category_classifier.h"

namespace sagrid {

struct Mesh;

struct BurnerCapRule {
  int minCaps = 3;  // equal round flat parts in the family
  // Each cap at least this share of the mesh's largest extent across (the real sinks' round
  // knobs: at most 0.038; real ranges' caps: 0.066 to 0.15).
  float minDiameterShare = 0.05f;
};

// A round flat part of a mesh and its family: the part (isRoundFlatPart, kMinInstanceTriangles or
// more), then its round flat copies (congruentParts within kCopyTolerance); each one's box width
// (the larger horizontal extent) as a share of the mesh's largest extent, the part's first.
struct RoundFlatFamily {
  std::size_t part = 0;  // index in connectedParts(mesh)
  std::vector<float> widthShares;
};

// One entry per round flat part of `mesh` (z-up mesh frame), in connectedParts' order (a family of
// n parts appears n times, once from each); none for an empty mesh. `sagrid info --parts` lists
// them.
std::vector<RoundFlatFamily> roundFlatFamilies(const Mesh& mesh);

// Whether a part of `mesh` at least rule.minDiameterShare wide has, with itself, at least
// rule.minCaps members of its round flat family that wide: the mesh's burner caps.
bool hasBurnerCaps(const Mesh& mesh, const BurnerCapRule& rule = {});

// `decision` unchanged unless it files the object under "sink"; then, when `hasCaps` (asked only
// then: hasBurnerCaps of the object's mesh) holds, the same decision with category and best
// "stove" and byBurnerCaps set.
CategoryDecision withBurnerCaps(const CategoryDecision& decision,
                                const std::function<bool()>& hasCaps);

}  // namespace sagrid
