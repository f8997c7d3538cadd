// Pictures of features for people: a view of the object with every pixel coloured by one
// feature channel of the voxel its ray hits (viridis-like colour map), to check at a glance
// that features vary where they should (knobs, burners, spouts).
#pragma once

#include <string>

#include "core/features/feature_grid.h"
#include "core/render/view_camera.h"

namespace sagrid {

struct Mesh;

// `mesh` in its mesh frame (the grid's normalization maps it). Values are scaled from the
// channel's min..max over the object; background black. Returns PNG bytes.
std::string renderFeaturePreviewPng(const Mesh& mesh, const FeatureGrid& grid, int channel,
                                    const ViewCamera& camera, int size);

// The camera previews use: three-quarter view from the front-left, above.
ViewCamera previewCamera();

}  // namespace sagrid
