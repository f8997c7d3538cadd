// A point on one of a row of equal parts carried onto the others: fused by a shared corner but
// drawn in a material of their own, or parts of their own.
#include "core/geometry/points_on_copies.h"

#include <gtest/gtest.h>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// A 1 m panel with three 4 cm knobs in a row on its top, each touching the panel at one corner
// (one connected mesh), drawn in a material of their own.
Mesh panelWithKnobRow() {
  Mesh mesh = test::box({0, 0, 0}, {1, 0.2f, 0.5f});
  for (float x : {0.2f, 0.5f, 0.8f}) test::append(mesh, test::box({x, 0.2f, 0.5f}, {x + 0.04f, 0.24f, 0.54f}));
  mesh.materials = {Material{"panel"}, Material{"knob"}};
  mesh.triangleMaterials.assign(mesh.triangles.size(), 1);
  std::fill(mesh.triangleMaterials.begin(), mesh.triangleMaterials.begin() + 12, 0);
  return mesh;
}

TEST(PointsOnCopies, APointOnOneKnobOfARowLandsOnTheOthersAtTheSameOffset) {
  const Mesh mesh = panelWithKnobRow();
  const auto copies = pointsOnCopies(mesh, {0.52f, 0.24f, 0.53f});  // on the middle knob's face
  ASSERT_EQ(copies.size(), 2u);
  std::vector<float> xs = {copies[0].x(), copies[1].x()};
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], 0.22f, 1e-5f);
  EXPECT_NEAR(xs[1], 0.82f, 1e-5f);
  for (const auto& c : copies) {
    EXPECT_NEAR(c.y(), 0.24f, 1e-5f);
    EXPECT_NEAR(c.z(), 0.53f, 1e-5f);
  }
}

TEST(PointsOnCopies, APointOnNoSmallPartOrOnAPartWithoutCopiesHasNone) {
  const Mesh mesh = panelWithKnobRow();
  EXPECT_TRUE(pointsOnCopies(mesh, {0.5f, 0.1f, 0.0f}).empty());  // the panel: no small part
  EXPECT_TRUE(pointsOnCopies(mesh, {5, 5, 5}).empty());           // on nothing
  EXPECT_TRUE(pointsOnCopies(mesh, {NAN, 0, 0}).empty());
  EXPECT_TRUE(pointsOnCopies(Mesh{}, {0, 0, 0}).empty());
  Mesh lone = test::box({0, 0, 0}, {1, 0.2f, 0.5f});
  test::append(lone, test::box({0.5f, 0.2f, 0.5f}, {0.54f, 0.24f, 0.54f}));
  EXPECT_TRUE(pointsOnCopies(lone, {0.52f, 0.24f, 0.53f}).empty());  // one knob: no copy
}

TEST(PointsOnCopies, WhereNoPartSeparatesThemTheCreasePatchesCopy) {
  // Two burner rings raised out of one hob body, same shape: no connected or material part is
  // small, but each ring's top is a crease patch, a copy of the other's.
  const Mesh hob = test::plateWithPlateaus(20, 10, 0.1f, {{4, 6, 4, 6}, {14, 16, 4, 6}});
  const auto copies = pointsOnCopies(hob, {0.52f, 0.48f, 0.1f});
  ASSERT_EQ(copies.size(), 1u);
  EXPECT_TRUE(copies[0].isApprox(Eigen::Vector3f(1.52f, 0.48f, 0.1f), 1e-5f));
  // One ring alone has no copy.
  EXPECT_TRUE(pointsOnCopies(test::plateWithPlateaus(10, 10, 0.1f, {{4, 6, 4, 6}}),
                             {0.52f, 0.48f, 0.1f})
                  .empty());
}

}  // namespace
}  // namespace sagrid
