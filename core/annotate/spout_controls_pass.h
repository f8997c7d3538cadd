// The spout-controls pass (core/points/spout_controls.h) on a toggle-button prediction: a point on
// the spout's part (the part that holds a fluid-source point) moves to the small part near it where
// the field is lowest, projected onto the surface like the model's own points. annotate, eval and
// the GUI (through annotate) run it on sinks before the repeated-parts pass, so that a handle it
// reaches gets its pair.
#pragma once

#include <vector>

#include "core/annotate/annotate.h"
#include "core/points/spout_controls.h"

namespace sagrid {

// Leaves predictions of other types as they are. `spouts`: the fluid-source points (normalized
// frame); `parts` from normalizedParts.
void applySpoutControls(ModelPrediction& prediction, const std::vector<ConnectedPart>& parts,
                        const std::vector<Eigen::Vector3f>& spouts, const FeatureGrid& features,
                        const SurfaceScene& scene, UpAxis fileUp,
                        const ExtractionSettings& extraction, const SpoutControlSettings& settings);

}  // namespace sagrid
