#include "core/annotate/part_ownership_pass.h"

namespace sagrid {

void applyPartOwnership(std::vector<ModelPrediction>& predictions,
                        const std::vector<ConnectedPart>& parts, const FeatureGrid& features,
                        const SurfaceScene& scene, UpAxis fileUp,
                        const PartOwnershipSettings& settings) {
  if (predictions.empty()) return;
  std::vector<TypedPoints> byType;
  for (const auto& prediction : predictions)
    byType.push_back(
        {prediction.points, prediction.type == "togglebutton" || prediction.type == "heatsource"});
  byType = ownParts(std::move(byType), parts, features.resolution, settings);
  for (std::size_t t = 0; t < predictions.size(); ++t)
    setPoints(predictions[t], std::move(byType[t].points), features, scene, fileUp);
}

}  // namespace sagrid
