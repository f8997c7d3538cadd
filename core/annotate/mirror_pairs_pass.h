// The mirror-pair pass of the automatic count (core/points/mirror_pairs.h) on a model's
// prediction: the twins of its points on a mirror-symmetric object, and of toggle buttons across
// the spout beside them (a mixer's hot and cold handles), projected onto the surface like the
// model's own points. annotate, eval and the GUI (through annotate) run it after the
// coarse-to-fine pass and before the printed marks; `--no-mirror-pairs` switches it off.
#pragma once

#include <vector>

#include "core/annotate/annotate.h"
#include "core/points/mirror_pairs.h"

namespace sagrid {

// Adds the twins to `prediction` (points and surface): across the object's mirror plane, then
// across the vertical plane through the nearest of `anchors` (normalized frame; mirrorAnchors).
// Unchanged on an asymmetric object without anchors.
void applyMirrorPairs(ModelPrediction& prediction, const FeatureGrid& features,
                      const SurfaceScene& scene, UpAxis fileUp,
                      const ExtractionSettings& extraction,
                      const std::vector<Eigen::Vector3f>& anchors = {},
                      const MirrorPairSettings& settings = {});

// The points among an object's predictions `made` so far that anchor the pairs of a prediction of
// `type`: the fluid sources for toggle buttons (the models of a folder run in name order, spouts
// before taps), none for other types.
std::vector<Eigen::Vector3f> mirrorAnchors(const std::vector<ModelPrediction>& made,
                                           const std::string& type);

}  // namespace sagrid
