// Repeated parts: the instances an automatic count misses when they are copies of one part. A
// range's knobs in a row, a hob's equal burner caps, a tap's hot and cold handles are usually
// separate parts of the mesh with the same shape; the network's field over such a row is often
// one long shallow valley, and the count keeps one or two points of it. A point that lies on a
// small part gets a point on every copy of that part (moved, turned or mirrored) where the field
// is low enough and no point is yet. A mixer's two handles are often predicted as one point
// between them, at the spout: a point on no small part moves onto a nearby pair of equal parts.
// Works in the normalized frame.
#pragma once

#include <vector>

#include "core/geometry/connected_parts.h"
#include "core/points/point_extraction.h"

namespace sagrid {

// The share of a copy's spacing within which another point makes it taken
// (RepeatedPartSettings::separationBySpacing).
constexpr float kSpacingShare = 0.75f;

// A round flat part (RepeatedPartSettings::roundFlatSeeds): horizontal extents within this share
// of the larger, height at most this share of the smaller.
constexpr float kRoundShare = 0.15f, kFlatShare = 0.5f;

// Whether `part` (normalized frame, z up) is round and flat as a burner's cap.
bool isRoundFlatPart(const ConnectedPart& part);

struct RepeatedPartSettings {
  // The small parts a point belongs to: a knob, a handle, a burner cap, not a panel or the cabinet.
  PartContact contact;
  // Copies: congruentParts within this relative tolerance.
  float congruenceTolerance = kCopyTolerance;
  // Above 1, a part scaled by up to this factor is a copy too (similarityScale), and a point's
  // offset from the part's centroid scales with it: a range's wok burner is its other burners'
  // cap made larger. 1 = congruent copies only.
  float maxCopyScale = 1.0f;
  // Only round flat parts repeat (a burner's cap: its two horizontal extents within
  // kRoundShare of each other, at most kFlatShare of the smaller high): a hob's grate bars are
  // copies of one another too, and a burner point on one must not put points on the others.
  bool roundFlatSeeds = false;
  // The field at a copy's point: its smallest predicted distance within two voxels must not
  // exceed the point's own by more than this (normalized units); < 0 = no condition.
  float maxDistanceAbovePoint = 0.05f;
  // A copy gets no point when a point lies within this many voxels of where it would go, or within
  // the count's suppression radius (ExtractionSettings::nmsRadius) when that is larger, or within
  // touchVoxels of its box: the spokes of one cross handle are copies of one another too (on the
  // 300 generated wall-fixture sinks, curator edits 0.76 -> 0.73 per object with the radius).
  int separationVoxels = 3;
  // Instead of the suppression radius, at most kSpacingShare of the distance from the copy to the
  // nearest other copy of its family (at least separationVoxels): a range's knobs can stand closer
  // together than the count's radius, and with it a row with a point on every other knob got no
  // more. Off where one instance is several copies (the spokes of a cross handle).
  bool separationBySpacing = false;
  // A point on no small part (a handle predicted at the spout's foot, on the spout or the basin)
  // moves to the nearest small part within this many voxels that has exactly one copy (a hot and
  // a cold handle) where the field is low enough, and its copy gets a point; 0 = never.
  float pairReachVoxels = 6.0f;
  // Knobs that are whole parts (a range's): a point on a small part with copies that is at least
  // this many voxels across (a knob, not an indicator light) moves to the centre of the part's box
  // before the copies get points, and a point on no small part to the nearest such part within
  // pairReachVoxels (a row, not only a pair) where the field is low enough. The network's valley
  // along a row of knobs puts its points between two knobs or beside the row; a knob is labelled
  // at its centre. The copies of such a part are taken by a point within kSpacingShare of their
  // spacing even where the row is tighter than separationVoxels. 0 = off (a handle's point is on
  // its lever, not at the part's centre).
  float snapPartVoxels = 0.0f;
  // With snapPartVoxels: a point on no small part moves onto the nearest knob within
  // pairReachVoxels whose row (the part and its copies) has at least this many knobs, whatever the
  // field there. A row of equal knobs is surer than the network's field beside it: on a real range
  // the toggle points lay 7 cm below its row of four knobs, on the bar of the oven door, where the
  // field at the knobs was higher than maxDistanceAbovePoint allows. 0 = the field decides always.
  int sureKnobRow = 0;
  // With sureKnobRow: a knob part scaled by up to this factor that continues such a row (on its
  // line, at most kRowReachSpacings of its spacing beyond its end: core/geometry/part_rows.h) gets
  // a point too, whatever the field; a real range's oven knob is its burner knobs made 1.23 times
  // larger, one and a half spacings beyond them. 1 = off.
  float rowContinuationScale = 1.0f;
};

// Row continuations (RepeatedPartSettings::rowContinuationScale): a centroid within this share of
// the row's spacing from its line, at most this many spacings beyond its end.
constexpr float kRowLineShare = 0.25f, kRowReachSpacings = 2.0f;

// `points` plus, for each point (best first), a point on every copy of the part it lies on: of the
// small parts that hold it and have a copy, the one with the largest area (of equal ones, the
// nearest); a point on no small part is first moved to the centroid of a paired part near it
// (pairReachVoxels); with snapPartVoxels, every point is first moved onto its knob (above). The new
// point keeps its offset from the part's centroid, moved to the copy's centroid (mirrored across
// the plane between the two centroids when the copy's box is not the part's box moved). `parts` are
// in the normalized frame (connectedParts of the normalized mesh). New points come after the given
// ones; a new point's distance is the field's smallest within two voxels, its confidence
// exp(-distance / confidenceScale). A copy whose box holds one of `occupied` (within touch: another
// type's points) gets no point. Unchanged without parts or field.
std::vector<ExtractedPoint> completeRepeatedParts(
    const PredictedField& field, const std::vector<ExtractedPoint>& points,
    const std::vector<ConnectedPart>& parts, const ExtractionSettings& extraction,
    const RepeatedPartSettings& settings = {}, const std::vector<Eigen::Vector3f>& occupied = {});

}  // namespace sagrid
