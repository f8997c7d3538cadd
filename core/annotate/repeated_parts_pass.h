// The repeated-parts pass of the automatic count (core/points/repeated_parts.h) on a model's
// prediction: a point on every copy of the part a point lies on (a row of equal knobs), projected
// onto the surface like the model's own points. annotate, eval and the GUI (through annotate) run
// it after the mirror pairs and before the printed marks; `--no-repeated-parts` switches it off.
#pragma once

#include <vector>

#include "core/annotate/annotate.h"
#include "core/geometry/connected_parts.h"
#include "core/points/repeated_parts.h"

namespace sagrid {

// The connected parts of `mesh` (z-up mesh frame) in the normalized frame of `normalization`.
std::vector<ConnectedPart> normalizedParts(const Mesh& mesh, const Normalization& normalization);

// Adds the points on copies to `prediction` (points and surface), and moves a point onto a nearby
// pair of equal parts (re-projected), when it is of toggle buttons, or of heat sources with
// `settings.roundFlatSeeds` (burner caps only); other types are left as they are: a hob's burners
// come in several sizes and sit among grate bars that are copies of one another (on the bench val
// split, burner precision fell 90 -> 82 % with the pass on them, every part repeating). A copy
// that holds one of `occupied` (normalized frame: the points of other types) gets no point.
// `parts` from normalizedParts.
void applyRepeatedParts(ModelPrediction& prediction, const std::vector<ConnectedPart>& parts,
                        const FeatureGrid& features, const SurfaceScene& scene, UpAxis fileUp,
                        const ExtractionSettings& extraction,
                        const RepeatedPartSettings& settings = {},
                        const std::vector<Eigen::Vector3f>& occupied = {});

// The points (normalized frame) of every prediction but the one at `except`.
std::vector<Eigen::Vector3f> pointsOfOtherTypes(const std::vector<ModelPrediction>& predictions,
                                                std::size_t except);

}  // namespace sagrid
