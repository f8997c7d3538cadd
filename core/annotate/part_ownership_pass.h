// The part-ownership pass (core/points/part_ownership.h) on an object's predictions: points of a
// type on a small part that a more confident point of another type lies on are dropped, and so
// are knob and burner points on a large part (the grate, a panel) when other points of their type
// lie on small parts.
// annotate, eval and the GUI (through annotate) run it on the automatic count once every model of
// the category has predicted; `--no-part-ownership` switches it off.
#pragma once

#include <string>
#include <vector>

#include "core/annotate/annotate.h"
#include "core/geometry/connected_parts.h"
#include "core/points/part_ownership.h"

namespace sagrid {

// `parts` from normalizedParts (core/annotate/repeated_parts_pass.h); the surface points of the
// kept points stay as they were.
void applyPartOwnership(std::vector<ModelPrediction>& predictions,
                        const std::vector<ConnectedPart>& parts, const FeatureGrid& features,
                        const SurfaceScene& scene, UpAxis fileUp,
                        const PartOwnershipSettings& settings = {});

}  // namespace sagrid
