// The spout-outlet pass (core/points/spout_outlets.h) on a model's prediction: fluid-source points
// that lie on no overhang move to the overhang near them where the field is lowest, the outlet
// under a spout's tip, and are projected onto the surface like the model's own points. annotate,
// eval and the GUI (through annotate) run it on every fluid-source prediction after the count's
// other passes; `--no-spout-outlets` switches it off.
#pragma once

#include "core/annotate/annotate.h"
#include "core/points/spout_outlets.h"

namespace sagrid {

// Leaves predictions of other types as they are.
void applySpoutOutlets(ModelPrediction& prediction, const FeatureGrid& features,
                       const SurfaceScene& scene, UpAxis fileUp,
                       const ExtractionSettings& extraction,
                       const SpoutOutletSettings& settings = {});

}  // namespace sagrid
