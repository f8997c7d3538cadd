#include "core/annotate/repeated_parts_pass.h"

#include "core/features/feature_grid.h"
#include "core/grid/normalization.h"
#include "core/points/surface_projection.h"

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
  auto points =
      completeRepeatedParts(prediction.field, prediction.points, parts, extraction, settings);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i < prediction.points.size() && points[i].position == prediction.points[i].position)
      continue;
    const SurfacePoint s =
        projectToSurface(points[i].position, features.normalization, scene, fileUp);
    if (i < prediction.surface.size())
      prediction.surface[i] = s;
    else
      prediction.surface.push_back(s);
  }
  prediction.points = std::move(points);
}

}  // namespace sagrid
