// The point the "extend" action adds (E in the GUI): one step past a point along its row, for rows
// the "copies" action cannot carry (keys and zones printed on a glass top, knobs fused into the
// panel): the step is from the point's nearest neighbour of its type to the point, so a curator
// who placed two points of a row presses E once for each further one. Positions in the file's
// frame, as labels store them.
#pragma once

#include <optional>
#include <vector>

#include "core/labels/labels.h"

namespace sagrid::ui {

class AnnotationDocument;

// The step's end may lie this share of the step from the surface (a row on a curved panel);
// farther, the row has left the object.
inline constexpr float kRowOffSurface = 0.1f;

// The point one step past point `index` (its type, on the surface nearest the step's end, with
// the surface's normal there), or nullopt where the point has no other point of its type, the
// step ends more than kRowOffSurface of a step from the surface, or a point of the type already
// lies within kCopyTaken of a step there.
std::optional<AffordancePoint> nextPointInRow(const AnnotationDocument& document, int index);
// The same among `points` (file frame) on the document's mesh: what the row would give with
// points the document does not hold (yet).
std::optional<AffordancePoint> nextPointInRow(const AnnotationDocument& document,
                                              const std::vector<AffordancePoint>& points, int index);

}  // namespace sagrid::ui
