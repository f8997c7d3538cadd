// A point placed on one of a row of equal parts (a stove's knobs, its burner caps or rings, a
// tap's two handles) carried onto every copy of that part: the curator places one and gets the
// others in one step. Parts are connectedAndMaterialParts (core/geometry/material_parts.h), so a
// knob fused into the panel but drawn in its own material counts; copies are PartCopies (same
// triangle count, area and spread within kCopyTolerance). The point keeps its offset from its
// part's centroid on each copy (rows are translations; a mirrored copy at its centre is exact).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/geometry/connected_parts.h"

namespace sagrid {

struct Mesh;

// Where `point`, lying on part `on` of `parts`, lands on each of that part's copies (`copies.of`,
// in its order): its offset from the part's centroid kept. The one rule the curator's copies (R)
// and the point decision's copy links (core/points/point_candidates.h) share.
std::vector<Eigen::Vector3f> placesOnCopies(const Eigen::Vector3f& point, std::size_t on,
                                            const std::vector<ConnectedPart>& parts,
                                            const PartCopies& copies);

// Where `point` (the mesh's frame) lands on each copy of the small part it lies on, the copies in
// the parts' order; empty when it lies on no small part (box diagonal at most kSmallPartDiagonal
// of the mesh's largest extent, the box grown by kCopyTouchShare of that extent) or the part has
// no copy. Where no such part has copies, the crease patch it lies on does the same
// (core/geometry/crease_patches.h: a burner's ring modelled into the hob, its copies the others).
std::vector<Eigen::Vector3f> pointsOnCopies(const Mesh& mesh, const Eigen::Vector3f& point);

// How near a point must lie to a part's box to be on it, as a share of the mesh's largest extent.
inline constexpr float kCopyTouchShare = 0.01f;

}  // namespace sagrid
