#include "core/features/voxel_aggregation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/common/error.h"
#include "core/render/trellis_views.h"

namespace sagrid {
namespace {

// Brute-force reference, written from torch.nn.functional.grid_sample's definition
// (align_corners=False, zeros padding): grid g = 2 uv - 1, ix = ((g + 1) W - 1) / 2.
std::vector<float> gridSample(const FeatureMap& map, float u, float v) {
  const float gx = 2 * u - 1, gy = 2 * v - 1;
  const float ix = ((gx + 1) * map.width - 1) / 2, iy = ((gy + 1) * map.height - 1) / 2;
  std::vector<float> out(map.channels, 0.0f);
  const int ixW = static_cast<int>(std::floor(ix)), iyN = static_cast<int>(std::floor(iy));
  for (int yy = iyN; yy <= iyN + 1; ++yy) {
    for (int xx = ixW; xx <= ixW + 1; ++xx) {
      const float w = (1 - std::abs(ix - xx)) * (1 - std::abs(iy - yy));
      if (xx < 0 || yy < 0 || xx >= map.width || yy >= map.height) continue;
      for (int c = 0; c < map.channels; ++c) {
        out[c] +=
            w * map.values[(static_cast<std::size_t>(yy) * map.width + xx) * map.channels + c];
      }
    }
  }
  return out;
}

// Nearest 2x2 texels' farthest depth vs the point's depth.
bool referenceVisible(const std::vector<float>& depth, int w, int h, float u, float v, float z,
                      float tol) {
  const int x0 = static_cast<int>(std::floor(u * w - 0.5f)),
            y0 = static_cast<int>(std::floor(v * h - 0.5f));
  float farthest = -1e30f;
  for (int y = y0; y <= y0 + 1; ++y)
    for (int x = x0; x <= x0 + 1; ++x) {
      if (x < 0 || y < 0 || x >= w || y >= h) return true;
      farthest = std::max(farthest, depth[static_cast<std::size_t>(y) * w + x]);
    }
  return z <= farthest + tol;
}

struct Scene {
  std::vector<Eigen::Vector3f> points;
  std::vector<ViewCamera> cameras;
  std::vector<FeatureMap> maps;
  std::vector<std::vector<float>> depths;
  int depthSize = 9;
};

Scene randomScene() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> coord(-0.5f, 0.5f), value(-1.0f, 1.0f), depth(1.4f, 2.6f);
  Scene s;
  for (int i = 0; i < 60; ++i) s.points.emplace_back(coord(rng), coord(rng), coord(rng));
  s.cameras = trellisViews(7, 11);
  for (std::size_t v = 0; v < s.cameras.size(); ++v) {
    FeatureMap m;
    m.resize(6 + static_cast<int>(v % 3), 5, 3);  // non-square maps catch x/y mix-ups
    for (float& x : m.values) x = value(rng);
    s.maps.push_back(m);
    std::vector<float> d(s.depthSize * s.depthSize);
    for (float& x : d) x = depth(rng);
    d[4] = kBackgroundDepth;
    s.depths.push_back(d);
  }
  return s;
}

TEST(VoxelAggregation, MeanEqualsBruteForceGridSampleAverage) {
  const Scene s = randomScene();
  VoxelAggregator agg(s.points, 3, Aggregation::Mean, 0.02f);
  for (std::size_t v = 0; v < s.cameras.size(); ++v) agg.addView(s.cameras[v], s.maps[v], nullptr);
  const std::vector<float> mean = agg.mean();
  for (std::size_t p = 0; p < s.points.size(); ++p) {
    std::vector<float> ref(3, 0.0f);
    for (std::size_t v = 0; v < s.cameras.size(); ++v) {
      const Eigen::Vector2f uv = s.cameras[v].project(s.points[p]);
      const auto sample = gridSample(s.maps[v], uv.x(), uv.y());
      for (int c = 0; c < 3; ++c) ref[c] += sample[c] / s.cameras.size();
    }
    EXPECT_EQ(agg.counts()[p], 7);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[p * 3 + c], ref[c], 1e-5f) << p << " " << c;
  }
}

TEST(VoxelAggregation, OcclusionAwareEqualsBruteForceOverVisibleViews) {
  const Scene s = randomScene();
  const float tol = 0.05f;
  VoxelAggregator a(s.points, 3, Aggregation::OcclusionAware, tol);
  VoxelAggregator b(s.points, 3, Aggregation::OcclusionAware, tol);  // merged partial
  for (std::size_t v = 0; v < s.cameras.size(); ++v) {
    const DepthMapRef d{s.depthSize, s.depthSize, s.depths[v].data()};
    (v % 2 ? a : b).addView(s.cameras[v], s.maps[v], &d);
  }
  a.merge(b);
  EXPECT_EQ(a.viewsAdded(), 7);
  const std::vector<float> mean = a.mean();
  int partial = 0;
  for (std::size_t p = 0; p < s.points.size(); ++p) {
    std::vector<float> sum(3, 0.0f);
    int count = 0;
    for (std::size_t v = 0; v < s.cameras.size(); ++v) {
      float z = 0;
      const Eigen::Vector2f uv = s.cameras[v].project(s.points[p], &z);
      if (!referenceVisible(s.depths[v], s.depthSize, s.depthSize, uv.x(), uv.y(), z, tol))
        continue;
      const auto sample = gridSample(s.maps[v], uv.x(), uv.y());
      for (int c = 0; c < 3; ++c) sum[c] += sample[c];
      ++count;
    }
    ASSERT_EQ(a.counts()[p], count) << p;
    partial += count > 0 && count < 7;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[p * 3 + c], count ? sum[c] / count : 0.0f, 1e-5f);
  }
  EXPECT_GT(partial, 10);  // the random depths do occlude some views of many points
}

TEST(VoxelAggregation, AddViewsOnAnyThreadCountEqualsOneViewAfterAnotherBitForBit) {
  Scene s = randomScene();
  // Enough points to be split between threads.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coord(-0.5f, 0.5f);
  while (s.points.size() < 6000) s.points.emplace_back(coord(rng), coord(rng), coord(rng));
  const float tol = 0.05f;
  VoxelAggregator one(s.points, 3, Aggregation::OcclusionAware, tol);
  std::vector<const ViewCamera*> cameras;
  std::vector<const FeatureMap*> maps;
  std::vector<DepthMapRef> depths;
  for (std::size_t v = 0; v < s.cameras.size(); ++v) {
    const DepthMapRef d{s.depthSize, s.depthSize, s.depths[v].data()};
    one.addView(s.cameras[v], s.maps[v], &d);
    cameras.push_back(&s.cameras[v]);
    maps.push_back(&s.maps[v]);
    depths.push_back(d);
  }
  for (int threads : {1, 2, 3, 5}) {
    VoxelAggregator batched(s.points, 3, Aggregation::OcclusionAware, tol);
    // In two batches, as the embedded backend adds them.
    const std::size_t half = cameras.size() / 2;
    batched.addViews({cameras.begin(), cameras.begin() + half}, {maps.begin(), maps.begin() + half},
                     {depths.begin(), depths.begin() + half}, threads);
    batched.addViews({cameras.begin() + half, cameras.end()}, {maps.begin() + half, maps.end()},
                     {depths.begin() + half, depths.end()}, threads);
    EXPECT_EQ(batched.viewsAdded(), one.viewsAdded());
    EXPECT_EQ(batched.counts(), one.counts()) << threads;
    EXPECT_EQ(batched.sums(), one.sums()) << threads;  // exactly: the same order of additions
  }
  VoxelAggregator mismatched(s.points, 3, Aggregation::OcclusionAware, tol);
  EXPECT_THROW(mismatched.addViews(cameras, maps, {}, 2), Error);  // occlusion needs depths
}

TEST(VoxelAggregation, BilinearSampleAtTexelCentreIsTheTexel) {
  FeatureMap m;
  m.resize(4, 3, 2);
  for (std::size_t i = 0; i < m.values.size(); ++i) m.values[i] = static_cast<float>(i);
  float out[2] = {0, 0};
  addBilinearSample(m, {(2 + 0.5f) / 4, (1 + 0.5f) / 3}, 1.0f, out);
  EXPECT_FLOAT_EQ(out[0], m.at(2, 1)[0]);
  EXPECT_FLOAT_EQ(out[1], m.at(2, 1)[1]);
  // Half-way between texels (0,0) and (1,0).
  float mid[2] = {0, 0};
  addBilinearSample(m, {1.0f / 4, 0.5f / 3}, 1.0f, mid);
  EXPECT_FLOAT_EQ(mid[0], 0.5f * (m.at(0, 0)[0] + m.at(1, 0)[0]));
  // Corner of the image: only a quarter of the corner texel (zeros padding).
  float corner[2] = {0, 0};
  addBilinearSample(m, {0.0f, 0.0f}, 1.0f, corner);
  EXPECT_FLOAT_EQ(corner[1], 0.25f * m.at(0, 0)[1]);
}

TEST(VoxelAggregation, RejectsMismatchedInputs) {
  VoxelAggregator agg({Eigen::Vector3f::Zero()}, 2, Aggregation::OcclusionAware, 0.01f);
  FeatureMap m;
  m.resize(2, 2, 3);
  const ViewCamera cam = ViewCamera::lookAtOrigin(0, 0, 2, 0.7f);
  EXPECT_THROW(agg.addView(cam, m, nullptr), Error);
  m.resize(2, 2, 2);
  EXPECT_THROW(agg.addView(cam, m, nullptr), Error);  // occlusion test needs depth
}

}  // namespace
}  // namespace sagrid
