#include "core/points/spout_outlets.h"

#include <limits>

#include "core/points/field_lookup.h"

namespace sagrid {

std::vector<ExtractedPoint> moveToOutlets(
    const PredictedField& field, const std::vector<ExtractedPoint>& points,
    const std::vector<std::vector<OutletCandidate>>& candidates,
    const ExtractionSettings& extraction, const SpoutOutletSettings& settings) {
  if (field.voxels.empty() || candidates.size() != points.size()) return points;
  const float voxel = 1.0f / static_cast<float>(field.resolution);
  const DenseField dense(field.voxels, field.resolution);
  std::vector<ExtractedPoint> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ExtractedPoint point = points[i];
    bool atOutlet = false;
    const OutletCandidate* best = nullptr;
    float bestField = std::numeric_limits<float>::infinity(), bestReach = 0;
    for (const auto& c : candidates[i]) {
      // A landing that sees no sky is under a cover or inside a solid part (a handle's top over
      // its own bottom face).
      if (c.skyView < settings.minSkyView) continue;
      const float reach = (c.position - point.position).norm();
      if (reach <= settings.onOutletVoxels * voxel && c.drop >= settings.onOutletDropVoxels * voxel)
        atOutlet = true;
      if (c.drop < settings.minDropVoxels * voxel || c.drop > settings.maxDropVoxels * voxel)
        continue;
      const float f =
          nearbyDistance(field, dense, voxelContaining(c.position, field.resolution), 1);
      if (f < bestField || (f == bestField && reach < bestReach))
        best = &c, bestField = f, bestReach = reach;
    }
    if (!atOutlet && best &&
        (settings.maxDistanceAbovePoint < 0 ||
         bestField <= point.distance + settings.maxDistanceAbovePoint)) {
      point.position = best->position;
      point.distance = bestField;
      point.confidence = confidenceOf(bestField, extraction);
    }
    const bool moved = point.position != points[i].position;
    bool suppressed = false;
    for (const auto& kept : out)
      suppressed = suppressed || (kept.position - point.position).norm() < extraction.nmsRadius;
    if (!moved || !suppressed) out.push_back(point);
  }
  return out;
}

}  // namespace sagrid
