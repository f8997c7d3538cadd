#include "core/features/feature_preview.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/geometry/surface_scene.h"
#include "core/grid/normalization.h"
#include "core/mesh/mesh.h"
#include "core/render/multiview_renderer.h"
#include "core/render/trellis_views.h"
#include "core/render/view_export.h"

namespace sagrid {

namespace {
// Five stops of viridis, linearly interpolated.
Eigen::Vector3f colourMap(float t) {
  static const Eigen::Vector3f stops[5] = {{0.267f, 0.005f, 0.329f},
                                           {0.229f, 0.322f, 0.546f},
                                           {0.128f, 0.567f, 0.551f},
                                           {0.369f, 0.789f, 0.383f},
                                           {0.993f, 0.906f, 0.144f}};
  t = std::clamp(t, 0.0f, 1.0f) * 4.0f;
  const int i = std::min(3, static_cast<int>(t));
  return stops[i] + (t - i) * (stops[i + 1] - stops[i]);
}
}  // namespace

ViewCamera previewCamera() {
  return ViewCamera::lookAtOrigin(static_cast<float>(-M_PI / 2 - 0.6), 0.5f, kTrellisCameraRadius,
                                  kTrellisFovDegrees / 180.0f * static_cast<float>(M_PI));
}

std::string renderFeaturePreviewPng(const Mesh& mesh, const FeatureGrid& grid, int channel,
                                    const ViewCamera& camera, int size) {
  if (channel < 0 || channel >= grid.channels) {
    throw InvalidArgument("feature channel " + std::to_string(channel) + " out of range (0.." +
                          std::to_string(grid.channels - 1) + ")");
  }
  const Mesh normalized = normalizedCopy(mesh, grid.normalization);
  const SurfaceScene scene(normalized);
  RenderedView view = MultiViewRenderer(normalized, scene).render(camera, size);
  // Voxel lookup: dense map from linear index to row.
  const int res = grid.resolution;
  std::vector<int> row(static_cast<std::size_t>(res) * res * res, -1);
  float lo = 1e30f, hi = -1e30f;
  for (std::size_t v = 0; v < grid.voxels.size(); ++v) {
    const VoxelIndex& x = grid.voxels[v];
    row[(static_cast<std::size_t>(x.i) * res + x.j) * res + x.k] = static_cast<int>(v);
    lo = std::min(lo, grid.featuresOf(v)[channel]);
    hi = std::max(hi, grid.featuresOf(v)[channel]);
  }
  const float range = hi > lo ? hi - lo : 1.0f;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * size + x;
      if (!view.mask[p]) continue;
      const Eigen::Vector3f hit =
          camera.position() +
          view.depth[p] * camera.rayDirection((x + 0.5f) / size, (y + 0.5f) / size);
      const VoxelIndex v = voxelContaining(hit, res);
      const int r = row[(static_cast<std::size_t>(v.i) * res + v.j) * res + v.k];
      // Light shading keeps the shape readable under the colour.
      const float shade =
          0.55f + 0.45f * std::abs(Eigen::Vector3f(view.normal[p * 3], view.normal[p * 3 + 1],
                                                   view.normal[p * 3 + 2])
                                       .dot(-camera.rayDirection(0.5f, 0.5f).normalized()));
      const Eigen::Vector3f c = r < 0 ? Eigen::Vector3f(0.5f, 0.5f, 0.5f)
                                      : colourMap((grid.featuresOf(r)[channel] - lo) / range);
      for (int k = 0; k < 3; ++k) view.rgb[p * 3 + k] = c[k] * shade;
    }
  }
  return encodeViewPng(view);
}

}  // namespace sagrid
