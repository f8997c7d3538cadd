// The mirror-pair pass of the automatic count (core/points/mirror_pairs.h) on a model's
// prediction: the twins of its points on a mirror-symmetric object, projected onto the surface
// like the model's own points. annotate, eval and the GUI (through annotate) run it after the
// coarse-to-fine pass and before the printed marks; `--no-mirror-pairs` switches it off.
#pragma once

#include "core/annotate/annotate.h"
#include "core/points/mirror_pairs.h"

namespace sagrid {

// Adds the twins to `prediction` (points and surface); unchanged on an asymmetric object.
void applyMirrorPairs(ModelPrediction& prediction, const FeatureGrid& features,
                      const SurfaceScene& scene, UpAxis fileUp,
                      const ExtractionSettings& extraction,
                      const MirrorPairSettings& settings = {});

}  // namespace sagrid
