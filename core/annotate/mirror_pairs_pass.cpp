#include "core/annotate/mirror_pairs_pass.h"

#include "core/points/surface_projection.h"

namespace sagrid {

std::string mirrorAnchorType(const std::string& type) {
  return type == "togglebutton" ? "fluidsource" : "";
}

void applyMirrorPairs(ModelPrediction& prediction, const FeatureGrid& features,
                      const SurfaceScene& scene, UpAxis fileUp,
                      const ExtractionSettings& extraction,
                      const std::vector<ModelPrediction>& earlier,
                      const MirrorPairSettings& settings) {
  auto points = completeMirrorPairs(prediction.field, prediction.points, extraction, settings);
  const std::string anchorType = mirrorAnchorType(prediction.type);
  std::vector<Eigen::Vector3f> anchors;
  for (const auto& other : earlier)
    if (!anchorType.empty() && other.type == anchorType)
      for (const auto& a : other.points) anchors.push_back(a.position);
  points = completeAnchoredPairs(prediction.field, points, anchors, extraction, settings);
  if (points.size() == prediction.points.size()) return;
  // Images come after the point they mirror: keep each original surface point, project the rest.
  std::vector<SurfacePoint> surface;
  std::size_t original = 0;
  for (const auto& p : points) {
    if (original < prediction.points.size() && p.position == prediction.points[original].position) {
      surface.push_back(prediction.surface[original++]);
    } else {
      surface.push_back(projectToSurface(p.position, features.normalization, scene, fileUp));
    }
  }
  prediction.points = std::move(points);
  prediction.surface = std::move(surface);
}

}  // namespace sagrid
