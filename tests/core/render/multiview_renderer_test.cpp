#include "core/render/multiview_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/geometry/surface_scene.h"
#include "core/grid/voxelize.h"
#include "core/render/trellis_views.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

constexpr float kFov = 40.0f / 180.0f * static_cast<float>(M_PI);

// Analytic ray-sphere: z-depth of the first hit (direction scaled to unit z-depth), or < 0.
float sphereDepth(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float r) {
  const float a = d.dot(d), b = 2 * o.dot(d), c = o.dot(o) - r * r;
  const float disc = b * b - 4 * a * c;
  if (disc < 0) return -1;
  return (-b - std::sqrt(disc)) / (2 * a);
}

TEST(MultiViewRenderer, SphereDepthNormalsAndMaskMatchAnalytic) {
  const float r = 0.4f;
  Mesh mesh = test::uvSphere(Eigen::Vector3f::Zero(), r, 64);
  test::paint(mesh, {0.8f, 0.2f, 0.1f});
  const SurfaceScene scene(mesh);
  const MultiViewRenderer renderer(mesh, scene);
  const ViewCamera cam = ViewCamera::lookAtOrigin(0.9f, 0.3f, 2.0f, kFov);
  const int size = 48;
  const RenderedView view = renderer.render(cam, size);
  // Tessellation error of a 64-ring sphere: r (1 - cos(pi / 128)) ~ 1.2e-4.
  int hits = 0, mismatches = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * size + x;
      const Eigen::Vector3f d = cam.rayDirection((x + 0.5f) / size, (y + 0.5f) / size);
      const float t = sphereDepth(cam.position(), d, r);
      const bool analyticHit = t > 0;
      if (analyticHit != (view.mask[p] == 1)) {
        ++mismatches;  // only at the silhouette, where polygon and circle differ
        continue;
      }
      if (!analyticHit) {
        EXPECT_EQ(view.depth[p], kBackgroundDepth);
        EXPECT_EQ(view.rgb[p * 3], 0.0f);
        continue;
      }
      ++hits;
      const Eigen::Vector3f n = (cam.position() + t * d).normalized();
      // Polygon vs sphere depth differs most at grazing angles (rim); tolerance grows there.
      const float facing = std::abs(n.dot(d.normalized()));
      EXPECT_NEAR(view.depth[p], t, 1e-3f / std::max(facing, 0.1f));
      const Eigen::Vector3f rendered(view.normal[p * 3], view.normal[p * 3 + 1],
                                     view.normal[p * 3 + 2]);
      EXPECT_GT(rendered.dot(n), 0.995f) << "pixel " << x << "," << y;
      EXPECT_NEAR(view.albedo[p * 3], 0.8f, 1e-5f);
      EXPECT_NEAR(view.albedo[p * 3 + 1], 0.2f, 1e-5f);
      EXPECT_LE(view.rgb[p * 3], 0.8f + 1e-5f);  // shading only darkens
    }
  }
  // Projected disc radius ~ r / sqrt(4 - r^2) / tan(20 deg) * size / 2 ~ 13.4 px: ~560 px.
  EXPECT_GT(hits, 500);
  EXPECT_LT(mismatches, 12);
}

TEST(MultiViewRenderer, PlaneSeenFromAboveHasConstantNormalAndAnalyticDepth) {
  const Mesh mesh = test::quadZ({-0.5f, -0.5f}, {0.5f, 0.5f}, 0.1f);
  const SurfaceScene scene(mesh);
  const MultiViewRenderer renderer(mesh, scene);
  const ViewCamera cam = ViewCamera::lookAtOrigin(0.2f, 1.2f, 2.0f, kFov);
  const RenderedView view = renderer.render(cam, 32);
  int hits = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * 32 + x;
      if (!view.mask[p]) continue;
      ++hits;
      EXPECT_NEAR(view.normal[p * 3 + 2], 1.0f, 1e-5f);
      const Eigen::Vector3f d = cam.rayDirection((x + 0.5f) / 32, (y + 0.5f) / 32);
      const float t = (0.1f - cam.position().z()) / d.z();
      EXPECT_NEAR(view.depth[p], t, 1e-4f);
    }
  }
  EXPECT_GT(hits, 300);
}

TEST(MultiViewRenderer, VoxelCentreProjectsOntoThePixelWhoseRayHitsIt) {
  // Camera round trip: a voxel the view sees projects to a pixel whose ray hits the surface in
  // that voxel or its direct neighbours; a surface point projects to the pixel whose ray hits
  // it within the pixel's footprint.
  const float r = 0.35f;
  const Mesh mesh = test::uvSphere(Eigen::Vector3f::Zero(), r, 96);
  const int res = 32;
  const VoxelGrid grid = voxelize(mesh, res);
  const SurfaceScene scene(mesh);
  const MultiViewRenderer renderer(mesh, scene);
  const ViewCamera cam = ViewCamera::lookAtOrigin(2.5f, -0.2f, 2.0f, kFov);
  const int size = 128;
  const RenderedView view = renderer.render(cam, size);
  auto hitAt = [&](const Eigen::Vector3f& p, float& footprint) -> std::optional<Eigen::Vector3f> {
    float depth = 0;
    const Eigen::Vector2f uv = cam.project(p, &depth);
    const int x = static_cast<int>(uv.x() * size), y = static_cast<int>(uv.y() * size);
    if (x < 0 || y < 0 || x >= size || y >= size) return std::nullopt;
    const std::size_t px = static_cast<std::size_t>(y) * size + x;
    if (!view.mask[px]) return std::nullopt;
    footprint = depth * 2.0f * std::tan(kFov / 2) / size;
    return cam.position() + view.depth[px] * cam.rayDirection((x + 0.5f) / size, (y + 0.5f) / size);
  };
  int checked = 0;
  for (const VoxelIndex& v : grid.occupiedVoxels()) {
    const Eigen::Vector3f c = voxelCenter(v, res);
    const Eigen::Vector3f toCam = (cam.position() - c).normalized();
    if (c.normalized().dot(toCam) < 0.7f) continue;  // facing the camera
    float footprint = 0;
    const auto hit = hitAt(c, footprint);
    ASSERT_TRUE(hit.has_value()) << v.i << "," << v.j << "," << v.k;
    const VoxelIndex h = voxelContaining(*hit, res);
    EXPECT_LE(std::max({std::abs(h.i - v.i), std::abs(h.j - v.j), std::abs(h.k - v.k)}), 1)
        << v.i << "," << v.j << "," << v.k;
    // The surface point on the sphere under the voxel centre: same pixel, footprint-close.
    const Eigen::Vector3f s = c.normalized() * r;
    const auto surfaceHit = hitAt(s, footprint);
    ASSERT_TRUE(surfaceHit.has_value());
    EXPECT_LT((*surfaceHit - s).norm(), 2.0f * footprint);
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(MultiViewRenderer, RenderEachVisitsEveryViewOnceAcrossThreads) {
  const Mesh mesh = test::box({-0.2f, -0.2f, -0.2f}, {0.2f, 0.2f, 0.2f});
  const SurfaceScene scene(mesh);
  const MultiViewRenderer renderer(mesh, scene);
  const auto cameras = trellisViews(10, 3);
  std::vector<int> seen(cameras.size(), 0);
  std::vector<int> covered(cameras.size(), 0);
  renderer.renderEach(cameras, 16, 3, [&](int i, int worker, const RenderedView& view) {
    EXPECT_LT(worker, 3);
    ++seen[i];
    for (auto m : view.mask) covered[i] += m;
    // Same as rendering that view alone.
    const RenderedView alone = renderer.render(cameras[i], 16);
    EXPECT_EQ(alone.depth, view.depth);
  });
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    EXPECT_EQ(seen[i], 1);
    EXPECT_GT(covered[i], 10);
  }
  EXPECT_THROW(renderer.renderEach(cameras, 8, 2,
                                   [](int i, int, const RenderedView&) {
                                     if (i == 5) throw std::runtime_error("stop");
                                   }),
               std::runtime_error);
}

}  // namespace
}  // namespace sagrid
