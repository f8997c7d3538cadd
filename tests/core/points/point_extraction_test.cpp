#include "core/points/point_extraction.h"

#include <gtest/gtest.h>

#include <random>

#include "core/common/error.h"
#include "support/synthetic_fields.h"

namespace sagrid {
namespace {

using test::nearestExtracted;
using test::onPlate;
using test::plateField;
constexpr int kRes = test::kPlateResolution;
const float kVoxel = 1.0f / kRes;

TEST(PointExtraction, ArgminFindsTheSmallestDistance) {
  const auto f = plateField({onPlate(7, 21)});
  const ExtractedPoint p = argminPoint(f, {});
  EXPECT_LT((p.position - onPlate(7, 21)).norm(), 1e-6f);
  EXPECT_FLOAT_EQ(p.distance, 0.0f);
  EXPECT_FLOAT_EQ(p.confidence, 1.0f);
  ExtractionSettings s;
  s.confidenceScale = 0.02f;
  PredictedField shifted = f;
  for (auto& d : shifted.distances) d += 0.02f;
  EXPECT_NEAR(argminPoint(shifted, s).confidence, std::exp(-1.0f), 1e-5f);
}

TEST(PointExtraction, RejectsEmptyAndMismatchedFields) {
  PredictedField empty;
  EXPECT_THROW(argminPoint(empty, {}), InvalidArgument);
  auto f = plateField({onPlate(1, 1)});
  f.distances.pop_back();
  EXPECT_THROW(autoCountPoints(f, {}), InvalidArgument);
  EXPECT_THROW(kMeansPoints(plateField({onPlate(1, 1)}), 0, {}), InvalidArgument);
}

TEST(PointExtraction, AutoCountFindsFiveBurnersAmongNoise) {
  const std::vector<Eigen::Vector3f> burners = test::fiveBurnersOnPlate();
  const auto f = plateField(burners, 0.012f, 7);
  ExtractionSettings s;
  s.maxDistance = 0.03f;
  s.nmsRadius = 0.15f;
  const auto points = autoCountPoints(f, s);
  ASSERT_EQ(points.size(), 5u);
  for (const auto& b : burners) EXPECT_LE(nearestExtracted(points, b), 1.5f * kVoxel);
  // Sorted best first and confidences in (0, 1].
  for (std::size_t i = 1; i < points.size(); ++i)
    EXPECT_LE(points[i - 1].distance, points[i].distance);
  for (const auto& p : points) EXPECT_GT(p.confidence, 0.0f);
  // Without non-maximum suppression and the distance threshold, noise gives many more minima.
  s.nmsRadius = 0.0f;
  s.maxDistance = 1.0f;
  EXPECT_GT(autoCountPoints(plateField(burners, 0.04f, 7), s).size(), 5u);
}

TEST(PointExtraction, AutoCountKeepsOnlyCloseMinima) {
  // Two true instances; a third, shallow dip that is far from any affordance must be dropped.
  auto f = plateField({onPlate(5, 5), onPlate(26, 26)});
  for (std::size_t v = 0; v < f.voxels.size(); ++v) {
    const float d = (voxelCenter(f.voxels[v], kRes) - onPlate(5, 26)).norm();
    f.distances[v] = std::min(f.distances[v], 0.12f + d);
  }
  ExtractionSettings s;
  s.maxDistance = 0.05f;
  s.nmsRadius = 0.1f;
  const auto points = autoCountPoints(f, s);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LE(nearestExtracted(points, onPlate(5, 5)), 1e-5f);
  EXPECT_LE(nearestExtracted(points, onPlate(26, 26)), 1e-5f);
}

TEST(PointExtraction, KMeansWithKnownCountFindsEachInstance) {
  const std::vector<Eigen::Vector3f> knobs = {onPlate(4, 4), onPlate(4, 12), onPlate(4, 20),
                                              onPlate(4, 28)};
  const auto f = plateField(knobs, 0.003f, 3);
  const auto points = kMeansPoints(f, 4, {});
  ASSERT_EQ(points.size(), 4u);
  for (const auto& k : knobs) EXPECT_LE(nearestExtracted(points, k), 1.0f * kVoxel);
}

TEST(PointExtraction, KMeansCentroidRecoversTheCentreOfARing) {
  // A coil burner: the lowest predicted distances lie on a ring of radius 3 voxels around an
  // empty centre; the weighted centroid of the cluster is the burner centre.
  PredictedField f;
  f.resolution = kRes;
  const Eigen::Vector3f centre = onPlate(10, 10), other = onPlate(24, 24);
  for (int i = 0; i < kRes; ++i)
    for (int j = 0; j < kRes; ++j) {
      const Eigen::Vector3f p = onPlate(i, j);
      const float ringA = std::abs((p - centre).norm() - 3 * kVoxel);
      const float ringB = std::abs((p - other).norm() - 3 * kVoxel);
      if ((p - centre).norm() < 1.5f * kVoxel || (p - other).norm() < 1.5f * kVoxel) continue;
      f.voxels.push_back({i, j, 10});
      f.distances.push_back(std::min(ringA, ringB) + 0.5f * kVoxel);
    }
  const auto points = kMeansPoints(f, 2, {});
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LE(nearestExtracted(points, centre), 0.6f * kVoxel);
  EXPECT_LE(nearestExtracted(points, other), 0.6f * kVoxel);
}

TEST(PointExtraction, LocalMinimaOfAPlateauAreReportedOnce) {
  PredictedField f;
  f.resolution = 8;
  for (int i = 0; i < 8; ++i) {
    f.voxels.push_back({i, 0, 0});
    f.distances.push_back(i < 3 ? 0.1f : 0.1f + 0.01f * i);
  }
  const auto minima = localMinima(f);
  ASSERT_EQ(minima.size(), 1u);
  EXPECT_EQ(minima[0], 0u);
}

TEST(PointExtraction, CalibrationChoosesSettingsThatCountRight) {
  std::vector<PredictedField> fields;
  std::vector<std::vector<Eigen::Vector3f>> truths;
  const std::vector<std::vector<Eigen::Vector3f>> layouts = {
      {onPlate(6, 6), onPlate(6, 25)},
      {onPlate(6, 6), onPlate(25, 6), onPlate(25, 25)},
      {onPlate(16, 16)},
      {onPlate(6, 6), onPlate(6, 25), onPlate(25, 6), onPlate(25, 25)}};
  for (std::size_t l = 0; l < layouts.size(); ++l) {
    auto f = plateField(layouts[l], 0.004f, 11 + l);
    for (auto& d : f.distances) d += 0.008f;  // predictions never reach zero
    fields.push_back(f);
    truths.push_back(layouts[l]);
  }
  const ExtractionSettings s = calibrateExtraction(fields, truths);
  for (std::size_t l = 0; l < layouts.size(); ++l)
    EXPECT_EQ(autoCountPoints(fields[l], s).size(), layouts[l].size()) << "layout " << l;
}

}  // namespace
}  // namespace sagrid

namespace sagrid {
namespace {

TEST(PointExtraction, RefinementFindsAPointBetweenVoxelCentres) {
  // The true point lies half-way between two voxel centres; the refined argmin gets there.
  const Eigen::Vector3f truth = 0.5f * (onPlate(10, 10) + onPlate(11, 10));
  const auto f = plateField({truth});
  ExtractionSettings s;
  EXPECT_NEAR((argminPoint(f, s).position - truth).norm(), 0.5f * kVoxel, 1e-5f);
  s.refineVoxels = 2.0f;
  EXPECT_LT((argminPoint(f, s).position - truth).norm(), 0.1f * kVoxel);
  // Auto count refines every instance.
  s.maxDistance = 0.05f;
  const auto points = autoCountPoints(f, s);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_LT((points[0].position - truth).norm(), 0.1f * kVoxel);
}

}  // namespace
}  // namespace sagrid
