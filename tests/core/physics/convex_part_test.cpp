#include "core/physics/convex_part.h"

#include <random>

#include <gtest/gtest.h>

namespace sagrid::physics {
namespace {

std::vector<Eigen::Vector3f> cubeCornersWithInside() {
  std::vector<Eigen::Vector3f> points;
  for (int c = 0; c < 8; ++c) points.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.1f, 0.9f);
  for (int i = 0; i < 200; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  return points;
}

TEST(ConvexHull, CubeKeepsItsCornersAndVolume) {
  const auto hull = convexHull(cubeCornersWithInside());
  ASSERT_TRUE(hull);
  EXPECT_EQ(hull->vertices.size(), 8u);
  EXPECT_EQ(hull->triangles.size(), 12u);
  EXPECT_NEAR(hull->volume(), 1.0, 1e-6);  // > 0: triangles face outwards
  EXPECT_TRUE(hull->centroid().isApprox(Eigen::Vector3d(0.5, 0.5, 0.5), 1e-6));
  EXPECT_TRUE(hull->contains({0.5f, 0.5f, 0.5f}));
  EXPECT_FALSE(hull->contains({1.2f, 0.5f, 0.5f}));
  EXPECT_TRUE(hull->contains({1.05f, 0.5f, 0.5f}, 0.1f));
}

TEST(ConvexHull, VertexLimitIsKept) {
  std::vector<Eigen::Vector3f> sphere;
  std::mt19937 rng(5);
  std::normal_distribution<float> g;
  for (int i = 0; i < 2000; ++i) sphere.push_back(Eigen::Vector3f(g(rng), g(rng), g(rng)).normalized());
  const auto full = convexHull(sphere);
  const auto limited = convexHull(sphere, 32);
  ASSERT_TRUE(full && limited);
  EXPECT_GT(full->vertices.size(), 1000u);
  EXPECT_LE(limited->vertices.size(), 32u);
  EXPECT_GE(limited->vertices.size(), 4u);
  // The greedy hull keeps most of the volume (the full hull is ~4/3 pi).
  EXPECT_GT(limited->volume(), 0.75 * full->volume());
}

TEST(ConvexHull, FlatPointsNeedAThickness) {
  const std::vector<Eigen::Vector3f> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 0}};
  EXPECT_FALSE(convexHull(square));
  const auto slab = convexHull(square, 0, 0.02f);
  ASSERT_TRUE(slab);
  EXPECT_EQ(slab->vertices.size(), 8u);
  EXPECT_NEAR(slab->volume(), 0.02, 1e-4);
}

TEST(ConvexHull, CollinearPointsBecomeAThinBar) {
  const std::vector<Eigen::Vector3f> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  const auto bar = convexHull(line, 0, 0.1f);
  ASSERT_TRUE(bar);
  EXPECT_GE(bar->vertices.size(), 4u);
  EXPECT_NEAR(bar->volume(), 0.01 * std::sqrt(12.0), 1e-3);
  EXPECT_FALSE(convexHull({{1, 2, 3}, {1, 2, 3}}, 0, 0.1f));
}

}  // namespace
}  // namespace sagrid::physics
