// Spout controls: a toggle button is a handle, a lever or a knob, not the spout the water leaves
// by. On real sinks the network's toggle field is often lowest on the faucet's spout (the column of
// a widespread faucet between its two handles, a wall spout beside its side lever), where the
// fluid source is too. A toggle point on the part that holds a fluid-source point moves to the
// small part near it where the field is lowest; a pair of handles then gets its second point from
// the repeated-parts pass. Works in the normalized frame on the mesh's connected parts.
#pragma once

#include <vector>

#include "core/geometry/connected_parts.h"
#include "core/points/point_extraction.h"

namespace sagrid {

struct SpoutControlSettings {
  // The part a point lies on (PartContact): the small part whose grown box holds it.
  PartContact contact;
  // Candidate parts: small parts of at least kMinInstanceTriangles whose box lies within this many
  // voxels of the point, other than the spout's part. 0 = off.
  float reachVoxels = 0.0f;
  // A candidate's field (smallest predicted distance within two voxels of its centroid) may
  // exceed the point's own by at most this (normalized units); < 0 = no condition.
  float maxDistanceAbovePoint = 0.05f;
};

// `points` with each point that lies on the part of one of `spouts` (normalized frame: the
// fluid-source points) moved to the centroid of the candidate part where the field is lowest
// (ties: the nearest); its distance is the field's smallest within two voxels there, its
// confidence exp(-distance / confidenceScale). A moved point within the count's suppression
// radius (ExtractionSettings::nmsRadius) of another point is dropped. Unchanged without spouts,
// parts or field.
std::vector<ExtractedPoint> movePointsOffSpouts(const PredictedField& field,
                                                const std::vector<ExtractedPoint>& points,
                                                const std::vector<Eigen::Vector3f>& spouts,
                                                const std::vector<ConnectedPart>& parts,
                                                const ExtractionSettings& extraction,
                                                const SpoutControlSettings& settings);

}  // namespace sagrid
