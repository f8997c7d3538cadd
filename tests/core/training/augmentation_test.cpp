#include "core/training/augmentation.h"

#include <gtest/gtest.h>

#include <random>

#include "core/features/vector_channels.h"

namespace sagrid {
namespace {

constexpr int kRes = 16;

// An L-shaped set of voxels; channels: (normal_x, normal_y, normal_z, i-marker).
TrainingSample lSample() {
  TrainingSample s;
  s.id = "l";
  s.resolution = kRes;
  s.channels = 4;
  for (int i = 3; i < 12; ++i) {
    s.voxels.push_back({i, 4, 6});
    s.features.insert(s.features.end(), {1.0f, 0.0f, 0.0f, static_cast<float>(i)});
  }
  for (int j = 5; j < 9; ++j) {
    s.voxels.push_back({3, j, 6});
    s.features.insert(s.features.end(), {0.0f, 1.0f, 0.0f, 100.0f + j});
  }
  s.descriptor = {0.5f};
  s.targets = {voxelCenter({11, 4, 6}, kRes)};
  return s;
}

const float* featuresAt(const TrainingSample& s, const VoxelIndex& v) {
  for (std::size_t i = 0; i < s.voxels.size(); ++i)
    if (s.voxels[i] == v) return s.features.data() + i * s.channels;
  return nullptr;
}

TEST(VectorChannels, FindsXyzTriplesByName) {
  const auto t = vectorChannelTriples(
      {"albedo_r", "normal_x", "normal_y", "normal_z", "height", "dir_x", "dir_y", "other_z"});
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0], (std::array<int, 3>{1, 2, 3}));
}

TEST(Augmentation, QuarterTurnMovesVoxelsNormalsAndTargetsTogether) {
  const TrainingSample s = lSample();
  Augmentation a;
  a.quarterTurns = 1;
  const TrainingSample r = augment(s, a, {{0, 1, 2}});
  ASSERT_EQ(r.voxels.size(), s.voxels.size());
  // (x, y) -> (-y, x): voxel (i, j) -> (R - 1 - j, i).
  const float* f = featuresAt(r, {kRes - 1 - 4, 7, 6});
  ASSERT_NE(f, nullptr);
  EXPECT_FLOAT_EQ(f[3], 7.0f);
  EXPECT_NEAR(f[0], 0.0f, 1e-6f);  // normal +x turned to +y
  EXPECT_NEAR(f[1], 1.0f, 1e-6f);
  ASSERT_EQ(r.targets.size(), 1u);
  EXPECT_LT((r.targets[0] - voxelCenter({kRes - 1 - 4, 11, 6}, kRes)).norm(), 1e-6f);
  // Distances are preserved by a rigid motion: the target field moves with the voxels.
  const auto d0 = distanceTargets(s);
  const auto d1 = distanceTargets(r);
  std::vector<float> a0(d0), a1(d1);
  std::sort(a0.begin(), a0.end());
  std::sort(a1.begin(), a1.end());
  for (std::size_t i = 0; i < a0.size(); ++i) EXPECT_NEAR(a0[i], a1[i], 1e-6f);
}

TEST(Augmentation, ReflectionsAndShiftKeepTheStructure) {
  const TrainingSample s = lSample();
  Augmentation a;
  a.flipX = true;
  a.flipY = true;
  a.shift = Eigen::Vector3i(1, 2, -3);
  const TrainingSample r = augment(s, a, {{0, 1, 2}});
  const float* f = featuresAt(r, {kRes - 1 - 3 + 1, kRes - 1 - 6 + 2, 3});
  ASSERT_NE(f, nullptr);
  EXPECT_FLOAT_EQ(f[3], 106.0f);
  EXPECT_NEAR(f[1], -1.0f, 1e-6f);  // normal +y reflected to -y
  EXPECT_LT((r.targets[0] - voxelCenter({kRes - 1 - 11 + 1, kRes - 1 - 4 + 2, 3}, kRes)).norm(),
            1e-6f);
}

TEST(Augmentation, WarpIsSmoothAndMovesTargetsWithTheSurface) {
  const TrainingSample s = lSample();
  std::mt19937 rng(4);
  AugmentationRanges ranges;
  ranges.rotate = ranges.reflect = ranges.translate = false;
  ranges.warpVoxels = 1.5f;
  const Augmentation a = randomAugmentation(s, ranges, rng);
  ASSERT_FALSE(a.warp.empty());
  const TrainingSample w = augment(s, a, {{0, 1, 2}});
  // No voxel moves more than the warp amplitude (+ rounding to the voxel grid).
  for (const auto& v : s.voxels) {
    const Eigen::Vector3f moved = a.warpPoint(voxelCenter(v, kRes));
    EXPECT_LE((moved - voxelCenter(v, kRes)).norm() * kRes, 1.5f * std::sqrt(3.0f) + 1e-4f);
  }
  EXPECT_GE(w.voxels.size(), s.voxels.size() - 3);  // at most a few voxels merge
  EXPECT_LT((w.targets[0] - a.warpPoint(s.targets[0])).norm(), 1e-6f);
  // The warped target stays where the warped tip voxel is (within a voxel's rounding).
  const auto d = distanceTargets(w);
  EXPECT_LT(*std::min_element(d.begin(), d.end()), std::log1p(0.9f / kRes));
}

TEST(Augmentation, RandomShiftKeepsEveryVoxelInsideTheGrid) {
  const TrainingSample s = lSample();
  AugmentationRanges ranges;
  ranges.warpVoxels = 0;
  for (unsigned seed = 0; seed < 50; ++seed) {
    std::mt19937 rng(seed);
    const Augmentation a = randomAugmentation(s, ranges, rng);
    EXPECT_EQ(augment(s, a, {}).voxels.size(), s.voxels.size()) << "seed " << seed;
  }
}

}  // namespace
}  // namespace sagrid

namespace sagrid {
namespace {

TEST(TrainingSample, DistanceTargetsAreLogDistancesOptionallyCapped) {
  TrainingSample s;
  s.resolution = 4;
  s.voxels = {{0, 0, 0}, {3, 3, 3}};
  s.targets = {voxelCenter({0, 0, 0}, 4)};
  const float far = (voxelCenter({3, 3, 3}, 4) - s.targets[0]).norm();
  auto d = distanceTargets(s);
  EXPECT_FLOAT_EQ(d[0], 0.0f);
  EXPECT_FLOAT_EQ(d[1], std::log1p(far));
  d = distanceTargets(s, 0.2f);
  EXPECT_FLOAT_EQ(d[1], std::log1p(0.2f));
  s.targets.clear();
  EXPECT_THROW(distanceTargets(s), std::exception);
}

}  // namespace
}  // namespace sagrid
