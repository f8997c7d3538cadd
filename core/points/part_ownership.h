// Part ownership: one small part of a mesh is one affordance or none. A stove's knob is never one
// of its burners, a tap's spout never its handle; yet the network, unsure, often puts points of
// two types on one small part (a burner point on every knob of the row, a handle point on the
// spout). And knobs and burner caps are parts of their own: when some of an object's knob points
// lie on small parts, its knob points on a large part sit on the grate of a hob or on the cabinet
// front, which the network takes for rows of knobs; burner points on the grate between the caps
// likewise. Works in the normalized frame.
#pragma once

#include <vector>

#include "core/geometry/connected_parts.h"
#include "core/points/point_extraction.h"

namespace sagrid {

struct PartOwnershipSettings {
  // The small part a point lies on (partAt), as the repeated-parts pass's.
  PartContact contact;
  // Large parts: a panel, the grate, the cabinet (box diagonal, normalized units). Between the two
  // sizes lie a tap's turned handles whose boxes grow with the turn: neither.
  float largePartDiagonal = 0.4f;
  // A point on a large part moves onto the nearest small part within this many voxels (box
  // distance) that no point of its type lies on and no other type owns, instead of being dropped;
  // 0 = never.
  float reachVoxels = 4.0f;
  // Feet: small parts that stand on the object's support plane (their box reaches within
  // half a voxel of the lowest point of every part) and rise no higher than this above it
  // (normalized units). A knob or a burner is never a foot, yet a hot plate's four feet look like
  // knobs to the network and are copies of one another, so the repeated-parts and mirror-pair
  // passes multiply a point on one. 0 = no foot rule.
  float footHeight = 0.06f;
  // One knob, one burner cap: of a type's points on one small part only the surest stays (the
  // repeated-parts and mirror-pair passes can put a second point on a knob's grip or skirt).
  bool onePointPerPart = true;
  // Strays from a full row: when every copy of one part (at least three: a range's knobs) has a
  // point of a type, that type's points farther than this many times the row's spacing (the
  // median distance from a copy to the nearest other) from every copy of every full row go: the
  // network takes a display or a badge at the back for one more knob. 0 = no such rule.
  float strayRowSpacings = 2.5f;
};

// The points of one type: `ownParts` when the type's instances are parts of their own (toggle
// buttons, heat sources).
struct TypedPoints {
  std::vector<ExtractedPoint> points;
  bool ownParts = false;
};

// `byType` with points dropped: first, where points of several types lie on one small part, those
// of every type but the one of the most confident point there (the part's owner; a type with
// ownParts that has a point on every copy of the part, at least three, owns it before a surer
// point of a type that has not: a range's row of knobs), except that a type never loses all its
// points (its most confident one stays); then, of a type with ownParts that still has a point on a
// small part, every point on no small part and on a large part, unless it can move onto a free
// small part within reach; then, of a type with ownParts, every point on a foot, unless it is the
// type's last; then, of a type with ownParts, every point on a small part that a surer point of its
// type lies on; last, of a type with ownParts, the strays from the full rows (strayRowSpacings).
// The kept points keep their order. `parts` in the normalized frame; `resolution` is the field's (a
// voxel is 1 / resolution). Unchanged without parts.
std::vector<TypedPoints> ownParts(std::vector<TypedPoints> byType,
                                  const std::vector<ConnectedPart>& parts, int resolution,
                                  const PartOwnershipSettings& settings = {});

}  // namespace sagrid
