#include "core/annotate/mirror_pairs_pass.h"

#include "core/points/surface_projection.h"

namespace sagrid {

std::vector<Eigen::Vector3f> mirrorAnchors(const std::vector<ModelPrediction>& made,
                                           const std::string& type) {
  std::vector<Eigen::Vector3f> anchors;
  if (type != "togglebutton") return anchors;
  for (const auto& other : made)
    if (other.type == "fluidsource")
      for (const auto& a : other.points) anchors.push_back(a.position);
  return anchors;
}

void applyMirrorPairs(ModelPrediction& prediction, const FeatureGrid& features,
                      const SurfaceScene& scene, UpAxis fileUp,
                      const ExtractionSettings& extraction,
                      const std::vector<Eigen::Vector3f>& anchors,
                      const MirrorPairSettings& settings) {
  auto points = completeMirrorPairs(prediction.field, prediction.points, extraction, settings);
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
