#include "core/annotate/spout_outlet_pass.h"

#include <algorithm>

#include "core/geometry/overhangs.h"
#include "core/grid/normalization.h"

namespace sagrid {

void applySpoutOutlets(ModelPrediction& prediction, const FeatureGrid& features,
                       const SurfaceScene& scene, UpAxis fileUp,
                       const ExtractionSettings& extraction, const SpoutOutletSettings& settings) {
  if (prediction.type != "fluidsource" || prediction.points.empty()) return;
  const Normalization& normalization = features.normalization;
  const auto meshLength = [&](float voxels) {
    return normalization.lengthToMesh(voxels / static_cast<float>(prediction.field.resolution));
  };
  OverhangSearch search;
  search.radius = meshLength(settings.searchVoxels);
  search.step = meshLength(0.5f);
  search.minDrop = meshLength(std::min(settings.onOutletDropVoxels, settings.minDropVoxels));
  search.maxDrop = meshLength(settings.maxDropVoxels);
  search.minClearance = meshLength(settings.clearanceVoxels);
  std::vector<std::vector<OutletCandidate>> candidates;
  for (const auto& point : prediction.points) {
    auto& near = candidates.emplace_back();
    for (const auto& overhang : overhangsNear(scene, normalization.toMesh(point.position), search))
      near.push_back({normalization.toNormalized(overhang.position),
                      overhang.drop * normalization.scale, overhang.skyView});
  }
  setPoints(prediction,
            moveToOutlets(prediction.field, prediction.points, candidates, extraction, settings),
            features, scene, fileUp);
}

}  // namespace sagrid
