#include "core/annotate/spout_controls_pass.h"

namespace sagrid {

void applySpoutControls(ModelPrediction& prediction, const std::vector<ConnectedPart>& parts,
                        const std::vector<Eigen::Vector3f>& spouts, const FeatureGrid& features,
                        const SurfaceScene& scene, UpAxis fileUp,
                        const ExtractionSettings& extraction,
                        const SpoutControlSettings& settings) {
  if (prediction.type != "togglebutton") return;
  setPoints(
      prediction,
      movePointsOffSpouts(prediction.field, prediction.points, spouts, parts, extraction, settings),
      features, scene, fileUp);
}

}  // namespace sagrid
