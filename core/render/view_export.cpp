#include "core/render/view_export.h"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/thread_count.h"
#include "core/geometry/surface_scene.h"
#include "core/render/multiview_renderer.h"
#include "core/render/trellis_views.h"

namespace sagrid {

namespace {
void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

std::string encodeDepthPng(const RenderedView& view) {
  // Depth of a normalized object seen from radius 2 lies in [2 - sqrt(3)/2, 2 + sqrt(3)/2],
  // inside [1, 3]: near is bright; 0 marks the background.
  std::vector<std::uint8_t> grey(view.pixelCount(), 0);
  for (std::size_t p = 0; p < view.pixelCount(); ++p) {
    if (!view.mask[p]) continue;
    grey[p] = static_cast<std::uint8_t>(
        std::clamp((3.0f - view.depth[p]) / 2.0f * 254.0f + 1.0f, 1.0f, 255.0f));
  }
  std::string bytes;
  if (!stbi_write_png_to_func(appendBytes, &bytes, view.width, view.height, 1, grey.data(),
                              view.width)) {
    throw Error("PNG encoding failed");
  }
  return bytes;
}
}  // namespace

std::string encodeViewPng(const RenderedView& view) {
  std::vector<std::uint8_t> rgba(view.pixelCount() * 4);
  for (std::size_t p = 0; p < view.pixelCount(); ++p) {
    for (int c = 0; c < 3; ++c) {
      rgba[p * 4 + c] = static_cast<std::uint8_t>(
          std::lround(std::clamp(view.rgb[p * 3 + c], 0.0f, 1.0f) * 255.0f));
    }
    rgba[p * 4 + 3] = view.mask[p] ? 255 : 0;
  }
  std::string bytes;
  if (!stbi_write_png_to_func(appendBytes, &bytes, view.width, view.height, 4, rgba.data(),
                              view.width * 4)) {
    throw Error("PNG encoding failed");
  }
  return bytes;
}

void exportViews(const Mesh& mesh, const std::vector<ViewCamera>& cameras, int size,
                 const std::filesystem::path& dir, bool withDepth) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw FileError(dir, "cannot create folder: " + ec.message());
  const SurfaceScene scene(mesh);
  const MultiViewRenderer renderer(mesh, scene);
  renderer.renderEach(cameras, size, defaultThreadCount(),
                      [&](int i, int, const RenderedView& view) {
                        char name[32];
                        std::snprintf(name, sizeof name, "%03d.png", i);
                        writeFileAtomic(dir / name, encodeViewPng(view));
                        if (withDepth) {
                          std::snprintf(name, sizeof name, "%03d_depth.png", i);
                          writeFileAtomic(dir / name, encodeDepthPng(view));
                        }
                      });
  writeFileAtomic(dir / "transforms.json", camerasToJson(cameras).dump(1));
}

}  // namespace sagrid
