#include "core/points/spout_controls.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/points/field_lookup.h"

namespace sagrid {

namespace {
// Where a candidate's field is read: the smallest predicted distance within this many voxels.
constexpr int kFieldRadius = 2;
}  // namespace

std::vector<ExtractedPoint> movePointsOffSpouts(const PredictedField& field,
                                                const std::vector<ExtractedPoint>& points,
                                                const std::vector<Eigen::Vector3f>& spouts,
                                                const std::vector<ConnectedPart>& parts,
                                                const ExtractionSettings& extraction,
                                                const SpoutControlSettings& settings) {
  if (settings.reachVoxels <= 0 || spouts.empty() || parts.empty() || field.voxels.empty() ||
      field.resolution <= 0)
    return points;
  const DenseField dense(field.voxels, field.resolution);
  const float voxel = 1.0f / static_cast<float>(field.resolution);
  const float touch = settings.contact.touchVoxels * voxel;
  const float maxDiagonal = settings.contact.maxPartDiagonal;
  std::vector<std::optional<std::size_t>> spoutParts;
  for (const auto& s : spouts) spoutParts.push_back(partAt(s, parts, touch, maxDiagonal));
  std::vector<ExtractedPoint> out = points;
  std::vector<bool> moved(out.size(), false);
  for (std::size_t i = 0; i < out.size(); ++i) {
    ExtractedPoint& p = out[i];
    const auto on = partAt(p.position, parts, touch, maxDiagonal);
    if (!on || std::find(spoutParts.begin(), spoutParts.end(), on) == spoutParts.end()) continue;
    std::optional<std::size_t> best;
    float bestField = 0, bestGap = 0;
    for (std::size_t q = 0; q < parts.size(); ++q) {
      if (q == *on || parts[q].triangles < kMinInstanceTriangles ||
          !isSmallPart(parts[q], maxDiagonal))
        continue;
      const float gap = parts[q].box.exteriorDistance(p.position);
      if (gap > settings.reachVoxels * voxel) continue;
      const float d = nearbyDistance(
          field, dense, voxelContaining(parts[q].centroid, field.resolution), kFieldRadius);
      if (!std::isfinite(d) ||
          (settings.maxDistanceAbovePoint >= 0 && d > p.distance + settings.maxDistanceAbovePoint))
        continue;
      if (!best || d < bestField || (d == bestField && gap < bestGap))
        best = q, bestField = d, bestGap = gap;
    }
    if (!best) continue;
    p.position = parts[*best].centroid;
    p.distance = bestField;
    p.confidence = confidenceOf(bestField, extraction);
    moved[i] = true;
  }
  // A moved point that lands within the count's suppression radius of an unmoved point or of a
  // moved one kept before it is dropped (the handle had its point already).
  std::vector<ExtractedPoint> kept;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto near = [&](const ExtractedPoint& o) {
      return (o.position - out[i].position).norm() <= extraction.nmsRadius;
    };
    if (moved[i]) {
      bool besideUnmoved = false;
      for (std::size_t j = 0; j < out.size(); ++j) besideUnmoved |= !moved[j] && near(out[j]);
      if (besideUnmoved || std::any_of(kept.begin(), kept.end(), near)) continue;
    }
    kept.push_back(out[i]);
  }
  return kept;
}

}  // namespace sagrid
