// The points the "copies" action adds (R in the GUI): the source point's type on every copy of
// the part it lies on (core/geometry/points_on_copies.h) where the document has no point of that
// type yet. Positions in the file's frame, as labels store them.
#pragma once

#include <vector>

#include "core/labels/labels.h"

namespace sagrid::ui {

class AnnotationDocument;

// A copy holding a point of the carried type within this share of the way to it keeps its own.
inline constexpr float kCopyTaken = 0.25f;

// Copies of `source` (not necessarily one of the document's points yet) for the copies of its
// part; each keeps the source's type, normal and fields but its position.
std::vector<AffordancePoint> pointsForCopies(const AnnotationDocument& document,
                                             const AffordancePoint& source);

}  // namespace sagrid::ui
