#include "core/annotate/mirror_pairs_pass.h"

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
  if (points.size() != prediction.points.size())
    setPoints(prediction, std::move(points), features, scene, fileUp);
}

}  // namespace sagrid
