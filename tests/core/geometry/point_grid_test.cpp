// The point grid against brute force: every point near a query is visited, the nearest distance
// within a reach is exact, queries outside the box and a box too large for its cells included.
#include "core/geometry/point_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace sagrid {
namespace {

std::vector<Eigen::Vector3f> scattered(std::size_t n, float extent) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> at(0.0f, extent);
  std::vector<Eigen::Vector3f> points;
  for (std::size_t i = 0; i < n; ++i) points.emplace_back(at(random), at(random), at(random));
  return points;
}

float bruteDistance(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& p, float reach) {
  float best = reach;
  for (const auto& q : points) best = std::min(best, (q - p).norm());
  return best;
}

TEST(PointGrid, NearestDistanceWithinAReachIsExactInsideAndOutsideTheBox) {
  // Cells a thousandth of the box across: enlarged to kMaxCellsPerSide a side, still exact.
  for (const float cell : {0.05f, 0.001f}) {
    const auto points = scattered(500, 1.0f);
    Eigen::AlignedBox3f box;
    for (const auto& p : points) box.extend(p);
    const PointGrid grid(points, box, cell);
    for (const auto& query : scattered(200, 1.4f)) {
      const Eigen::Vector3f p = query - Eigen::Vector3f::Constant(0.2f);  // some outside the box
      EXPECT_FLOAT_EQ(grid.distanceWithin(p, 0.08f), bruteDistance(points, p, 0.08f));
    }
  }
}

TEST(PointGrid, EveryPointInAQueryBoxIsVisitedOnce) {
  const auto points = scattered(300, 1.0f);
  Eigen::AlignedBox3f box;
  for (const auto& p : points) box.extend(p);
  const PointGrid grid(points, box, 0.1f);
  const Eigen::AlignedBox3f query(Eigen::Vector3f(0.2f, 0.3f, 0.1f), Eigen::Vector3f(0.45f, 0.6f, 0.5f));
  std::vector<int> visits(points.size(), 0);
  grid.forEachWithin(query, [&](int i) { ++visits[static_cast<std::size_t>(i)]; });
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_LE(visits[i], 1);
    if (query.contains(points[i])) EXPECT_EQ(visits[i], 1);
  }
}

TEST(PointGrid, FacingWayKeepsOrTurnsTheSense) {
  EXPECT_TRUE(facingWay(Eigen::Vector3f::UnitZ(), Eigen::Vector3f(0, 0.1f, -1)).isApprox(-Eigen::Vector3f::UnitZ()));
  EXPECT_TRUE(facingWay(Eigen::Vector3f::UnitX(), Eigen::Vector3f(1, 5, 0)).isApprox(Eigen::Vector3f::UnitX()));
}

}  // namespace
}  // namespace sagrid
