#include "core/physics/convex_decomposition.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "support/analytic_meshes.h"

namespace sagrid::physics {
namespace {

using test::append;
using test::box;

// A coarser grid than the default keeps the tests quick; the shapes are simple.
DecompositionOptions quick() {
  DecompositionOptions options;
  options.resolution = 64;
  return options;
}

void expectSimulatorReady(const Decomposition& d) {
  for (const auto& part : d.parts) {
    EXPECT_GE(part.vertices.size(), 4u);
    EXPECT_LE(part.vertices.size(), 64u);
    EXPECT_GT(part.volume(), 0.0);
  }
}

double totalVolume(const Decomposition& d) {
  double v = 0;
  for (const auto& p : d.parts) v += p.volume();
  return v;
}

// A basin: floor and four walls 0.1 thick around a 0.8 x 0.8 x 0.5 cavity open at the top.
Mesh basin() {
  Mesh m = box({0, 0, 0}, {1, 1, 0.1f});
  append(m, box({0, 0, 0.1f}, {0.1f, 1, 0.6f}));
  append(m, box({0.9f, 0, 0.1f}, {1, 1, 0.6f}));
  append(m, box({0.1f, 0, 0.1f}, {0.9f, 0.1f, 0.6f}));
  append(m, box({0.1f, 0.9f, 0.1f}, {0.9f, 1, 0.6f}));
  return m;
}

TEST(ConvexDecomposition, BoxIsOnePart) {
  const Decomposition d = decomposeConvex(box({0, 0, 0}, {2, 1, 0.5f}));
  ASSERT_EQ(d.parts.size(), 1u);
  expectSimulatorReady(d);
  EXPECT_NEAR(d.parts[0].volume(), 1.0, 0.01);
  EXPECT_TRUE(d.warnings.empty());
}

TEST(ConvexDecomposition, SphereIsOnePart) {
  const double volume = 4.0 / 3.0 * M_PI * 0.125;
  const Decomposition d = decomposeConvex(test::uvSphere({1, 2, 3}, 0.5f, 24), quick());
  ASSERT_EQ(d.parts.size(), 1u);
  expectSimulatorReady(d);
  // 64 vertices inscribed in a sphere keep most but not all of it.
  EXPECT_GT(d.parts[0].volume(), 0.85 * volume);
  EXPECT_LT(d.parts[0].volume(), 1.01 * volume);
  DecompositionOptions unlimited = quick();
  unlimited.maxVerticesPerPart = 0;
  const Decomposition full = decomposeConvex(test::uvSphere({1, 2, 3}, 0.5f, 24), unlimited);
  ASSERT_EQ(full.parts.size(), 1u);
  EXPECT_NEAR(full.parts[0].volume(), volume, 0.02 * volume);
}

TEST(ConvexDecomposition, LShapeIsTwoParts) {
  Mesh l = box({0, 0, 0}, {1, 0.3f, 0.3f});
  append(l, box({0, 0, 0.3f}, {0.3f, 0.3f, 1}));
  const Decomposition d = decomposeConvex(l, quick());
  ASSERT_EQ(d.parts.size(), 2u);
  expectSimulatorReady(d);
  EXPECT_NEAR(totalVolume(d), 0.3 * 0.3 * 1.7, 0.01);
  // The notch of the L is in no part.
  for (const auto& part : d.parts) EXPECT_FALSE(part.contains({0.65f, 0.15f, 0.65f}));
}

TEST(ConvexDecomposition, SeparatedBoxesAreTwoParts) {
  Mesh two = box({0, 0, 0}, {0.4f, 0.4f, 0.4f});
  append(two, box({0.6f, 0, 0}, {1, 0.4f, 0.4f}));
  const Decomposition d = decomposeConvex(two, quick());
  ASSERT_EQ(d.parts.size(), 2u);
  for (const auto& part : d.parts) EXPECT_FALSE(part.contains({0.5f, 0.2f, 0.2f}));
}

TEST(ConvexDecomposition, BasinStaysOpen) {
  const Decomposition d = decomposeConvex(basin());
  expectSimulatorReady(d);
  EXPECT_GE(d.parts.size(), 3u);
  EXPECT_LE(d.parts.size(), 32u);
  // The cavity's centre and a ball of radius 0.2 around it are free: a sphere can sit inside.
  for (const auto& part : d.parts) {
    EXPECT_FALSE(part.contains({0.5f, 0.5f, 0.35f}, 0.2f));
    EXPECT_FALSE(part.contains({0.5f, 0.5f, 0.3f}));
  }
  EXPECT_NEAR(totalVolume(d), 1 * 1 * 0.1 + 2 * 0.1 * 0.5 + 2 * 0.8 * 0.1 * 0.5, 0.03);
}

TEST(ConvexDecomposition, PartBudgetIsKept) {
  // Eight separate cubes with a budget of four: neighbours are merged, with a warning.
  Mesh cubes;
  for (int i = 0; i < 8; ++i) append(cubes, box({i * 0.4f, 0, 0}, {i * 0.4f + 0.2f, 0.2f, 0.2f}));
  DecompositionOptions options;
  options.maxParts = 4;
  const Decomposition d = decomposeConvex(cubes, options);
  EXPECT_EQ(d.parts.size(), 4u);
  EXPECT_FALSE(d.warnings.empty());
  expectSimulatorReady(d);
}

TEST(ConvexDecomposition, PlaneBecomesAThinPartWithAWarning) {
  const Decomposition d = decomposeConvex(test::quadZ({0, 0}, {1, 2}, 0.5f));
  ASSERT_EQ(d.parts.size(), 1u);
  expectSimulatorReady(d);
  EXPECT_FALSE(d.warnings.empty());
  const Eigen::Vector3d c = d.parts[0].centroid();
  EXPECT_NEAR(c.z(), 0.5, 0.02);
  EXPECT_LT(d.parts[0].volume(), 2.0 * 0.05);
}

TEST(ConvexDecomposition, ReportsProgressAndHonoursCancel) {
  DecompositionOptions options = quick();
  float last = -1;
  options.progress = [&](float f, const std::string&) {
    EXPECT_GE(f, last);
    last = f;
  };
  decomposeConvex(basin(), options);
  EXPECT_FLOAT_EQ(last, 1.0f);
  std::atomic<bool> cancel{true};
  options.cancel = &cancel;
  EXPECT_THROW(decomposeConvex(basin(), options), Cancelled);
}

TEST(ConvexDecomposition, BadInputGivesClearErrors) {
  EXPECT_THROW(decomposeConvex(Mesh{}), Error);
  Mesh point;
  point.positions = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  point.triangles = {{0, 1, 2}};
  EXPECT_THROW(decomposeConvex(point), Error);
  DecompositionOptions options;
  options.maxParts = 0;
  EXPECT_THROW(decomposeConvex(box({0, 0, 0}, {1, 1, 1}), options), InvalidArgument);
}

TEST(ConvexHullPart, WholeMeshHullAndFlatMesh) {
  const ConvexPart hull = convexHullPart(basin());
  EXPECT_NEAR(hull.volume(), 0.6, 1e-4);
  EXPECT_TRUE(hull.contains({0.5f, 0.5f, 0.35f}));
  const ConvexPart plate = convexHullPart(test::quadZ({0, 0}, {1, 1}, 0));
  EXPECT_EQ(plate.vertices.size(), 8u);
  EXPECT_NEAR(plate.volume(), 0.01, 1e-4);
  EXPECT_THROW(convexHullPart(Mesh{}), Error);
}

}  // namespace
}  // namespace sagrid::physics
