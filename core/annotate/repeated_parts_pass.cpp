#include "core/annotate/repeated_parts_pass.h"

#include "core/grid/normalization.h"

namespace sagrid {

std::vector<ConnectedPart> normalizedParts(const Mesh& mesh, const Normalization& normalization) {
  auto parts = connectedParts(mesh);
  for (auto& part : parts) {
    part.area *= normalization.scale * normalization.scale;
    part.spread *= normalization.scale;
    part.centroid = normalization.toNormalized(part.centroid);
    if (!part.box.isEmpty())
      part.box = Eigen::AlignedBox3f(normalization.toNormalized(part.box.min()),
                                     normalization.toNormalized(part.box.max()));
  }
  return parts;
}

void applyRepeatedParts(ModelPrediction& prediction, const std::vector<ConnectedPart>& parts,
                        const FeatureGrid& features, const SurfaceScene& scene, UpAxis fileUp,
                        const ExtractionSettings& extraction, const RepeatedPartSettings& settings,
                        const std::vector<Eigen::Vector3f>& occupied) {
  if (prediction.type != "togglebutton" &&
      !(prediction.type == "heatsource" && settings.roundFlatSeeds))
    return;
  setPoints(prediction,
            completeRepeatedParts(prediction.field, prediction.points, parts, extraction, settings,
                                  occupied),
            features, scene, fileUp);
}

std::vector<Eigen::Vector3f> pointsOfOtherTypes(const std::vector<ModelPrediction>& predictions,
                                                std::size_t except) {
  std::vector<Eigen::Vector3f> out;
  for (std::size_t m = 0; m < predictions.size(); ++m)
    if (m != except)
      for (const auto& p : predictions[m].points) out.push_back(p.position);
  return out;
}

}  // namespace sagrid
