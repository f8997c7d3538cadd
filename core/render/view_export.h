// Writes rendered views in the layout TRELLIS's render step produces: DIR/000.png ... (RGBA,
// black background, alpha = coverage) and DIR/transforms.json (camera_angle_x, Blender
// transform_matrix, plus OpenCV extrinsics and normalized intrinsics), so Python tools written
// for TRELLIS renders read ours. Optionally a depth preview per view (8-bit grey, z-depth 1..3
// mapped to 255..1, 0 = background).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/render/rendered_view.h"
#include "core/render/view_camera.h"

namespace sagrid {

struct Mesh;

// PNG bytes of a view's shaded RGB (alpha = mask).
std::string encodeViewPng(const RenderedView& view);

// Renders `cameras` of the normalized mesh at size x size and writes them to `dir` (created).
// Every file is written atomically.
void exportViews(const Mesh& normalizedMesh, const std::vector<ViewCamera>& cameras, int size,
                 const std::filesystem::path& dir, bool withDepth = false);

}  // namespace sagrid
