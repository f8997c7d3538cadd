// Spout outlets: a fluid source is where water leaves the faucet, on the underside of the spout's
// tip with open space below it down to the basin. On real sinks the network's field is often
// lowest on the faucet's handles or body (a pillar tap's top, a mixer's lever), a few centimetres
// from the outlet. A point with no overhang at it moves to the overhang near it where the field is
// lowest. Works in the normalized frame; the overhangs come from core/geometry/overhangs.h.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/points/point_extraction.h"

namespace sagrid {

struct OutletCandidate {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();  // normalized frame
  float drop = 0;                                      // open height below it (normalized units)
  float skyView = 0;                                   // Overhang::skyView of its landing point
};

struct SpoutOutletSettings {
  float searchVoxels = 10.0f;       // overhangs within this of a point are its candidates
  float onOutletVoxels = 1.5f;      // a point this close to one of them is at an outlet already...
  float onOutletDropVoxels = 1.5f;  // ... when the drop below that one is at least this
  float minDropVoxels = 5.0f;       // open height below an outlet a point moves to: at least...
  float maxDropVoxels = 40.0f;      // ... and at most
  float minSkyView = 0.5f;          // the landing below every candidate sees the sky
  float clearanceVoxels = 2.0f;     // the open gap's middle at least this far from every surface
  // A candidate's field (smallest predicted distance within a voxel) may exceed the point's own by
  // at most this (normalized units); < 0 = no condition.
  float maxDistanceAbovePoint = 0.02f;
};

// `points` with each point that has no candidate within onOutletVoxels moved to the candidate
// where the field is lowest (ties: the nearest). `candidates[i]` are point i's overhangs
// (normalized frame). A moved point's distance is the field's smallest within a voxel, its
// confidence exp(-distance / confidenceScale). A moved point that ends within the count's
// suppression radius of a point before it is dropped. Unchanged without field.
std::vector<ExtractedPoint> moveToOutlets(
    const PredictedField& field, const std::vector<ExtractedPoint>& points,
    const std::vector<std::vector<OutletCandidate>>& candidates,
    const ExtractionSettings& extraction, const SpoutOutletSettings& settings = {});

}  // namespace sagrid
