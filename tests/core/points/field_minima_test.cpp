// Basin depth (persistence) of the field's minima and the automatic count's relative threshold
// and depth test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/points/point_extraction.h"
#include "support/synthetic_fields.h"

namespace sagrid {
namespace {

using test::onPlate;
using test::plateField;
constexpr float kVoxel = 1.0f / test::kPlateResolution;

TEST(FieldMinima, BasinDepthIsWhereTheFieldMeetsABetterBasin) {
  // Two cones 20 voxels apart, the second 0.05 higher: along the line between them the field
  // rises to (separation + 0.05) / 2 before the second basin joins the first, so its depth is
  // (separation - 0.05) / 2, to within a voxel of the grid.
  const Eigen::Vector3f a = onPlate(6, 10), b = onPlate(26, 10);
  const auto f = test::plateFieldWithOffsets({a, b}, {0.0f, 0.05f});
  const auto minima = fieldMinima(f);
  ASSERT_EQ(minima.size(), 2u);
  EXPECT_TRUE(std::isinf(minima[0].persistence));
  EXPECT_LT((voxelCenter(f.voxels[minima[0].voxel], f.resolution) - a).norm(), 1e-5f);
  EXPECT_LT((voxelCenter(f.voxels[minima[1].voxel], f.resolution) - b).norm(), 1e-5f);
  const float separation = (a - b).norm();
  EXPECT_NEAR(minima[1].persistence, 0.5f * (separation - 0.05f), kVoxel);
}

// A voxel no occupied 26-neighbour of which is lower (on a plateau: the lowest index counts as
// lower), checked voxel by voxel.
bool isLocalMinimum(const PredictedField& f, std::size_t v) {
  for (std::size_t u = 0; u < f.voxels.size(); ++u) {
    const VoxelIndex &p = f.voxels[v], &q = f.voxels[u];
    const int reach = std::max({std::abs(p.i - q.i), std::abs(p.j - q.j), std::abs(p.k - q.k)});
    if (u == v || reach > 1) continue;
    if (f.distances[u] < f.distances[v] || (f.distances[u] == f.distances[v] && u < v))
      return false;
  }
  return true;
}

TEST(FieldMinima, EveryLocalMinimumOnceBestFirst) {
  const auto f = plateField({onPlate(4, 4), onPlate(20, 9), onPlate(28, 28)}, 0.04f, 5);
  const auto minima = fieldMinima(f);
  std::size_t expected = 0;
  for (std::size_t v = 0; v < f.voxels.size(); ++v) expected += isLocalMinimum(f, v);
  ASSERT_EQ(minima.size(), expected);
  ASSERT_GT(minima.size(), 3u);  // the noise makes dimples
  for (std::size_t i = 0; i < minima.size(); ++i) {
    EXPECT_TRUE(isLocalMinimum(f, minima[i].voxel)) << i;
    if (i == 0) continue;
    EXPECT_LE(f.distances[minima[i - 1].voxel], f.distances[minima[i].voxel]) << i;
    EXPECT_GE(minima[i].persistence, 0.0f) << i;
    EXPECT_TRUE(std::isfinite(minima[i].persistence)) << i;
  }
  const auto local = localMinima(f);
  ASSERT_EQ(local.size(), minima.size());
  for (std::size_t i = 0; i < local.size(); ++i) EXPECT_EQ(local[i], minima[i].voxel);
}

TEST(FieldMinima, DepthTestDropsNoiseDimplesWithoutSuppression) {
  // Five burners in a noisy field: with no suppression radius and a loose threshold every noise
  // dimple counts; requiring a basin deeper than the noise leaves the five.
  const std::vector<Eigen::Vector3f> burners = test::fiveBurnersOnPlate();
  const auto f = plateField(burners, 0.04f, 7);
  ExtractionSettings s;
  s.maxDistance = 0.1f;
  s.nmsRadius = 0.0f;
  EXPECT_GT(autoCountPoints(f, s).size(), 5u);
  s.minPersistence = 0.1f;
  const auto points = autoCountPoints(f, s);
  ASSERT_EQ(points.size(), 5u);
  for (const auto& burner : burners)
    EXPECT_LE(test::nearestExtracted(points, burner), 1.5f * kVoxel);
}

TEST(FieldMinima, ThresholdAboveTheBestKeepsEveryInstanceOfAFieldThatSitsHigh) {
  // A real cooker's field: every burner predicted 0.15 away. An absolute threshold keeps the
  // best one only; the same threshold counted from the best keeps all four.
  const std::vector<Eigen::Vector3f> burners = {onPlate(6, 6), onPlate(6, 25), onPlate(25, 6),
                                                onPlate(25, 25)};
  const auto f = test::plateFieldWithOffsets(burners, {0.15f, 0.16f, 0.17f, 0.18f});
  ExtractionSettings s;
  s.maxDistance = 0.04f;
  s.nmsRadius = 0.1f;
  EXPECT_EQ(autoCountPoints(f, s).size(), 1u);
  s.maxDistanceAboveBest = true;
  EXPECT_EQ(autoCountPoints(f, s).size(), 4u);
  s.maxDistance = 0.025f;  // best + 0.025 reaches the second and third only
  EXPECT_EQ(autoCountPoints(f, s).size(), 3u);
}

}  // namespace
}  // namespace sagrid

namespace sagrid {
namespace {

TEST(FieldMinima, KnownCountIgnoresTheAutomaticCountsDepthTest) {
  // Four knobs whose field sits 0.1 to 0.19 high: with the count given, k-means must find all four
  // even when the card's depth test and relative threshold would keep only the best minimum.
  const std::vector<Eigen::Vector3f> knobs = {test::onPlate(4, 4), test::onPlate(4, 12),
                                              test::onPlate(4, 20), test::onPlate(4, 28)};
  const auto f = test::plateFieldWithOffsets(knobs, {0.1f, 0.13f, 0.16f, 0.19f});
  ExtractionSettings s;
  s.maxDistance = 0.001f;
  s.maxDistanceAboveBest = true;
  s.minPersistence = 5.0f;
  ASSERT_EQ(autoCountPoints(f, s).size(), 1u);
  const auto points = kMeansPoints(f, 4, s);
  ASSERT_EQ(points.size(), 4u);
  for (const auto& k : knobs) EXPECT_LE(test::nearestExtracted(points, k), 1.0f * kVoxel);
}

}  // namespace
}  // namespace sagrid
