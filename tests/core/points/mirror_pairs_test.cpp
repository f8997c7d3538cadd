#include "core/points/mirror_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "support/synthetic_fields.h"

namespace sagrid {
namespace {

constexpr int kRes = 32;
const float kVoxel = 1.0f / kRes;

// A counter top (i 4..27, j 8..23, k 10) with a tap (a 2x2x3 column) at each given i along
// j 12..13 above it: taps at i and 31 - i make it mirror-symmetric about the plane i + i' = 31.
std::vector<VoxelIndex> counterWithTaps(const std::vector<int>& tapColumns) {
  std::vector<VoxelIndex> voxels;
  for (int i = 4; i <= 27; ++i)
    for (int j = 8; j <= 23; ++j) voxels.push_back({i, j, 10});
  for (int i : tapColumns)
    for (int a = 0; a < 2; ++a)
      for (int j = 12; j <= 13; ++j)
        for (int k = 11; k <= 13; ++k) voxels.push_back({i + a, j, k});
  return voxels;
}

// The tap whose column starts at i: the centre of its top.
Eigen::Vector3f tapTop(int i) {
  return 0.5f * (voxelCenter({i, 12, 13}, kRes) + voxelCenter({i + 1, 13, 13}, kRes));
}

// Field: distance to the nearest of `centres` plus that centre's offset.
PredictedField fieldOf(const std::vector<VoxelIndex>& voxels,
                       const std::vector<Eigen::Vector3f>& centres,
                       const std::vector<float>& offsets) {
  PredictedField f;
  f.resolution = kRes;
  f.voxels = voxels;
  for (const auto& v : voxels) {
    float best = std::numeric_limits<float>::infinity();
    for (std::size_t c = 0; c < centres.size(); ++c)
      best = std::min(best, (voxelCenter(v, kRes) - centres[c]).norm() + offsets[c]);
    f.distances.push_back(best);
  }
  return f;
}

ExtractionSettings suppression(float radius) {
  ExtractionSettings s;
  s.nmsRadius = radius;
  s.confidenceScale = 0.02f;
  return s;
}

TEST(MirrorPairs, FindsThePlaneOfASymmetricObject) {
  const auto plane = findMirrorPlane(counterWithTaps({7, 23}), kRes, 0.85f);
  ASSERT_TRUE(plane.has_value());
  EXPECT_EQ(plane->axis, 0);
  EXPECT_EQ(plane->indexSum, 31);
  EXPECT_FLOAT_EQ(plane->score, 1.0f);
  EXPECT_NEAR(plane->coordinate(kRes), 0.0f, 1e-6f);  // the middle of i 4..27 on a 32 grid
  const Eigen::Vector3f p = tapTop(7);
  EXPECT_LT((plane->mirror(p, kRes) - tapTop(23)).norm(), 1e-5f);
}

TEST(MirrorPairs, FindsAPlaneOffTheBoundingBoxMiddle) {
  // A shelf on one side widens the box: the symmetry stays where the taps are.
  auto voxels = counterWithTaps({7, 23});
  for (int i = 28; i <= 30; ++i) voxels.push_back({i, 15, 10});
  const auto plane = findMirrorPlane(voxels, kRes, 0.85f);
  ASSERT_TRUE(plane.has_value());
  EXPECT_EQ(plane->axis, 0);
  EXPECT_EQ(plane->indexSum, 31);
}

TEST(MirrorPairs, NoPlaneForAnAsymmetricObjectOrNoVoxels) {
  std::vector<VoxelIndex> ell;
  for (int i = 2; i < 30; ++i) ell.push_back({i, 2, 5});
  for (int j = 3; j < 30; ++j) ell.push_back({2, j, 5});
  EXPECT_FALSE(findMirrorPlane(ell, kRes, 0.85f).has_value());
  EXPECT_FALSE(findMirrorPlane({}, kRes, 0.85f).has_value());
}

TEST(MirrorPairs, AddsTheTwinTapTheCountMissed) {
  const auto voxels = counterWithTaps({7, 23});
  // The field's minimum at the left tap is deep, at the right one shallow: the count keeps one.
  const auto f = fieldOf(voxels, {tapTop(7), tapTop(23)}, {0.0f, 0.03f});
  const auto points = completeMirrorPairs(f, {test::pointOnField(f, tapTop(7))}, suppression(0.1f));
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LT((points[0].position - tapTop(7)).norm(), 1e-6f);
  EXPECT_LT((points[1].position - tapTop(23)).norm(), 1e-5f);
  // The field's smallest value near the image: the offset plus the nearest voxel centre's
  // distance to the tap's top (between four voxel centres).
  EXPECT_GE(points[1].distance, 0.03f);
  EXPECT_LE(points[1].distance, 0.03f + kVoxel);
  EXPECT_NEAR(points[1].confidence, std::exp(-points[1].distance / 0.02f), 1e-5f);
}

TEST(MirrorPairs, AddsATwinVoxelizedOneVoxelOff) {
  // The right tap landed one voxel further out (columns 24..25, where 23..24 would mirror 7..8),
  // as voxelization does to real taps: read in a small neighbourhood, half the left tap's voxels
  // have their exact image occupied, all of them one within a voxel.
  const auto voxels = counterWithTaps({7, 24});
  const auto f = fieldOf(voxels, {tapTop(7), tapTop(24)}, {0.0f, 0.03f});
  MirrorPairSettings settings;
  settings.neighbourhoodVoxels = 1;
  const auto points =
      completeMirrorPairs(f, {test::pointOnField(f, tapTop(7))}, suppression(0.1f), settings);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LT((points[1].position - tapTop(23)).norm(), 1e-5f);  // the exact image
  settings.matchToleranceVoxels = 0;
  EXPECT_EQ(completeMirrorPairs(f, {test::pointOnField(f, tapTop(7))}, suppression(0.1f), settings)
                .size(),
            1u);
}

TEST(MirrorPairs, NoTwinWhereTheShapeDiffers) {
  // One tap on a symmetric counter: the object is still symmetric (the tap is small), but the
  // tap's neighbourhood has nothing at its mirror image.
  const auto voxels = counterWithTaps({7});
  ASSERT_TRUE(findMirrorPlane(voxels, kRes, 0.85f).has_value());
  const auto f = fieldOf(voxels, {tapTop(7), tapTop(23)}, {0.0f, 0.0f});
  EXPECT_EQ(completeMirrorPairs(f, {test::pointOnField(f, tapTop(7))}, suppression(0.1f)).size(),
            1u);
}

TEST(MirrorPairs, NoTwinWhereTheFieldIsHigh) {
  const auto voxels = counterWithTaps({7, 23});
  const auto f = fieldOf(voxels, {tapTop(7), tapTop(23)}, {0.0f, 0.2f});
  EXPECT_EQ(completeMirrorPairs(f, {test::pointOnField(f, tapTop(7))}, suppression(0.1f)).size(),
            1u);
  MirrorPairSettings anyField;
  anyField.maxDistanceAbovePoint = -1;
  EXPECT_EQ(completeMirrorPairs(f, {test::pointOnField(f, tapTop(7))}, suppression(0.1f), anyField)
                .size(),
            2u);
}

TEST(MirrorPairs, NoTwinWhenBothAreFoundOrThePointIsOnThePlane) {
  const auto voxels = counterWithTaps({7, 23, 15});  // the middle tap covers i 15..16
  const auto f = fieldOf(voxels, {tapTop(7), tapTop(23), tapTop(15)}, {0.0f, 0.0f, 0.0f});
  const std::vector<ExtractedPoint> both{test::pointOnField(f, tapTop(23)),
                                         test::pointOnField(f, tapTop(7))};
  EXPECT_EQ(completeMirrorPairs(f, both, suppression(0.1f)).size(), 2u);
  const std::vector<ExtractedPoint> middle{test::pointOnField(f, tapTop(15))};
  EXPECT_EQ(completeMirrorPairs(f, middle, suppression(0.1f)).size(), 1u);
}

TEST(MirrorPairs, UnchangedWithoutPoints) {
  const auto voxels = counterWithTaps({7, 23});
  const auto f = fieldOf(voxels, {tapTop(7)}, {0.0f});
  EXPECT_TRUE(completeMirrorPairs(f, {}, suppression(0.1f)).empty());
}

// A mixer off the counter's middle: a spout column (i 10..11, up to k 15) between two handle
// columns (i 7..8 and 13..14, up to k 13), mirror-symmetric about the spout, not the counter. With
// `lever`, a single bar over the spout (k 16, i 7..14) instead of the handles.
std::vector<VoxelIndex> mixerOnCounter(bool lever) {
  auto voxels = counterWithTaps(lever ? std::vector<int>{} : std::vector<int>{7, 13});
  for (int i = 10; i <= 11; ++i)
    for (int j = 12; j <= 13; ++j)
      for (int k = 11; k <= 15; ++k) voxels.push_back({i, j, k});
  if (lever)
    for (int i = 7; i <= 14; ++i)
      for (int j = 12; j <= 13; ++j) voxels.push_back({i, j, 16});
  return voxels;
}
const Eigen::Vector3f kSpoutTop =
    0.5f * (voxelCenter({10, 12, 15}, kRes) + voxelCenter({11, 13, 15}, kRes));

TEST(MirrorPairs, AddsTheOtherHandleAcrossTheSpout) {
  const auto voxels = mixerOnCounter(false);
  const auto f = fieldOf(voxels, {tapTop(7), tapTop(13)}, {0.0f, 0.03f});
  // The handles are 6 voxels apart, within the count's suppression radius (0.3 = 9.6 voxels):
  // the object's own plane (the counter's middle) would not pair them either.
  const auto points =
      completeAnchoredPairs(f, {test::pointOnField(f, tapTop(7))}, {kSpoutTop}, suppression(0.3f));
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LT((points[0].position - tapTop(7)).norm(), 1e-6f);
  EXPECT_LT((points[1].position - tapTop(13)).norm(), 1e-5f);
  EXPECT_GE(points[1].distance, 0.03f);
  EXPECT_LE(points[1].distance, 0.03f + kVoxel);
  EXPECT_EQ(completeMirrorPairs(f, {test::pointOnField(f, tapTop(7))}, suppression(0.3f)).size(),
            1u);
}

TEST(MirrorPairs, NoTwinAcrossTheSpoutForOneLeverOverIt) {
  const auto voxels = mixerOnCounter(true);
  const Eigen::Vector3f leverEnd =
      0.5f * (voxelCenter({7, 12, 16}, kRes) + voxelCenter({8, 13, 16}, kRes));
  const Eigen::Vector3f otherEnd =
      0.5f * (voxelCenter({13, 12, 16}, kRes) + voxelCenter({14, 13, 16}, kRes));
  const auto f = fieldOf(voxels, {leverEnd, otherEnd}, {0.0f, 0.0f});
  EXPECT_EQ(
      completeAnchoredPairs(f, {test::pointOnField(f, leverEnd)}, {kSpoutTop}, suppression(0.3f))
          .size(),
      1u);
}

TEST(MirrorPairs, NoAnchoredTwinWithoutASpoutNearby) {
  const auto voxels = mixerOnCounter(false);
  const auto f = fieldOf(voxels, {tapTop(7), tapTop(13)}, {0.0f, 0.0f});
  const std::vector<ExtractedPoint> handle{test::pointOnField(f, tapTop(7))};
  EXPECT_EQ(completeAnchoredPairs(f, handle, {}, suppression(0.3f)).size(), 1u);
  // A spout 18 voxels away, beyond the 10-voxel reach.
  const Eigen::Vector3f farSpout = voxelCenter({25, 12, 11}, kRes);
  EXPECT_EQ(completeAnchoredPairs(f, handle, {farSpout}, suppression(0.3f)).size(), 1u);
  MirrorPairSettings longReach;
  longReach.anchorRadiusVoxels = 20;
  EXPECT_EQ(completeAnchoredPairs(f, handle, {kSpoutTop}, suppression(0.3f), longReach).size(), 2u);
}

TEST(MirrorPairs, NoTwinAcrossAPlaneTheSpoutIsNotSymmetricAbout) {
  // A nozzle reaches out from the spout's top towards +i (i 12..14, k 16..17): the plane through
  // the spout normal to i mirrors the handles onto each other, but it is not the spout's own
  // plane (a handle behind a spout is not mirrored to the basin in front of its outlet).
  auto voxels = mixerOnCounter(false);
  for (int i = 12; i <= 14; ++i)
    for (int j = 12; j <= 13; ++j)
      for (int k = 16; k <= 17; ++k) voxels.push_back({i, j, k});
  const auto f = fieldOf(voxels, {tapTop(7), tapTop(13)}, {0.0f, 0.03f});
  EXPECT_EQ(
      completeAnchoredPairs(f, {test::pointOnField(f, tapTop(7))}, {kSpoutTop}, suppression(0.3f))
          .size(),
      1u);
}

}  // namespace
}  // namespace sagrid
