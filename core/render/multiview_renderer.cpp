#include "core/render/multiview_renderer.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"

namespace sagrid {

namespace {
// Headlight shading: enough to show shape in the RGB images the 2D encoder sees, without the
// cost or noise of global illumination.
constexpr float kAmbient = 0.3f;

struct RayBuffers {
  std::vector<Eigen::Vector3f> origins;
  std::vector<Eigen::Vector3f> directions;
  std::vector<std::optional<SurfaceHit>> hits;
};

void renderInto(const Mesh& mesh, const SurfaceScene& scene, const ViewCamera& camera, int size,
                RenderedView& out, RayBuffers& rays) {
  out.resize(size, size);
  const std::size_t n = out.pixelCount();
  rays.origins.assign(n, camera.position());
  camera.pixelRayDirections(size, rays.directions);
  scene.intersectMany(rays.origins, rays.directions, rays.hits);
  for (std::size_t p = 0; p < n; ++p) {
    const auto& hit = rays.hits[p];
    if (!hit) {
      std::fill_n(&out.rgb[p * 3], 3, 0.0f);
      std::fill_n(&out.albedo[p * 3], 3, 0.0f);
      std::fill_n(&out.normal[p * 3], 3, 0.0f);
      out.depth[p] = kBackgroundDepth;
      out.mask[p] = 0;
      continue;
    }
    const Eigen::Vector3f albedo = mesh.albedo(hit->triangle, hit->u, hit->v);
    const Eigen::Vector3f viewDir = -rays.directions[p].normalized();
    const float shade = kAmbient + (1.0f - kAmbient) * std::abs(hit->normal.dot(viewDir));
    for (int c = 0; c < 3; ++c) {
      out.albedo[p * 3 + c] = albedo[c];
      out.rgb[p * 3 + c] = std::min(1.0f, albedo[c] * shade);
      out.normal[p * 3 + c] = hit->normal[c];
    }
    out.depth[p] = hit->distance;  // direction scaled to unit z: t is z-depth
    out.mask[p] = 1;
  }
}
}  // namespace

void MultiViewRenderer::render(const ViewCamera& camera, int size, RenderedView& out) const {
  RayBuffers rays;
  renderInto(m_mesh, m_scene, camera, size, out, rays);
}

RenderedView MultiViewRenderer::render(const ViewCamera& camera, int size) const {
  RenderedView out;
  render(camera, size, out);
  return out;
}

void MultiViewRenderer::renderEach(const std::vector<ViewCamera>& cameras, int size, int threads,
                                   const ViewConsumer& consume) const {
  threads = std::max(1, std::min<int>(threads, static_cast<int>(cameras.size())));
  std::exception_ptr error;
  std::mutex errorMutex;
  auto work = [&](int worker) {
    try {
      RenderedView view;
      RayBuffers rays;
      for (std::size_t i = worker; i < cameras.size(); i += threads) {
        renderInto(m_mesh, m_scene, cameras[i], size, view, rays);
        consume(static_cast<int>(i), worker, view);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace sagrid
