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
                        const ExtractionSettings& extraction,
                        const RepeatedPartSettings& settings) {
  if (prediction.type != "togglebutton") return;
  setPoints(prediction,
            completeRepeatedParts(prediction.field, prediction.points, parts, extraction, settings),
            features, scene, fileUp);
}

}  // namespace sagrid
