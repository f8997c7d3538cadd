#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/surface_openness.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

constexpr float kOffset = 1e-3f;

// A floor slab with a shelf over half of it: the floor under the shelf is covered, the other half
// open to the sky.
Mesh floorAndShelf() {
  Mesh mesh = test::box({0, 0, 0}, {1, 1, 0.1f});
  test::append(mesh, test::box({0, 0, 0.5f}, {1, 0.5f, 0.6f}));
  return mesh;
}

SurfaceOpenness opennessAt(const SurfaceScene& scene, const Eigen::Vector3f& point) {
  return surfaceOpenness(scene, scene.closestPoint(point), kOffset);
}

TEST(SurfaceOpenness, TheSkyAboveAndTheShelfOverheadAreToldApart) {
  const SurfaceScene scene(floorAndShelf());
  const SurfaceOpenness shelfTop = opennessAt(scene, {0.5f, 0.25f, 0.6f});
  EXPECT_FLOAT_EQ(shelfTop.openness, 1.0f);  // a convex top: every upward direction leaves
  EXPECT_TRUE(std::isinf(shelfTop.above));
  EXPECT_NEAR(shelfTop.below, kOffset, 1e-4f);  // straight down is the shelf itself

  const SurfaceOpenness covered = opennessAt(scene, {0.5f, 0.25f, 0.1f});
  EXPECT_NEAR(covered.above, 0.4f - kOffset, 1e-4f);
  const SurfaceOpenness open = opennessAt(scene, {0.5f, 0.9f, 0.1f});
  EXPECT_TRUE(std::isinf(open.above));
  EXPECT_GT(open.openness, covered.openness + 0.1f);
  EXPECT_LT(open.openness, 1.0f);     // the shelf's side still blocks a few directions
  EXPECT_GT(covered.openness, 0.0f);  // out between the floor and the shelf

  // The shelf's underside: read from below (its inside sees nothing leave), the floor 0.4 down.
  const SurfaceOpenness underside = opennessAt(scene, {0.5f, 0.25f, 0.5f});
  EXPECT_NEAR(underside.below, 0.4f - kOffset, 1e-4f);
  EXPECT_GT(underside.openness, 0.0f);
}

TEST(SurfaceOpenness, TrianglesFacingInwardReadTheSame) {
  Mesh flipped = floorAndShelf();
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  const SurfaceScene scene(floorAndShelf()), flippedScene(flipped);
  for (const Eigen::Vector3f point :
       {Eigen::Vector3f(0.5f, 0.25f, 0.1f), Eigen::Vector3f(0.5f, 0.9f, 0.1f),
        Eigen::Vector3f(0.5f, 0.25f, 0.5f)}) {
    const SurfaceOpenness a = opennessAt(scene, point), b = opennessAt(flippedScene, point);
    EXPECT_FLOAT_EQ(a.openness, b.openness);
    EXPECT_EQ(std::isinf(a.above), std::isinf(b.above));
    EXPECT_NEAR(std::min(a.below, 10.0f), std::min(b.below, 10.0f), 1e-4f);
  }
}

TEST(SurfaceOpenness, WhereNoDirectionLeavesEitherSideTheSideTheTriangleFacesIsRead) {
  // Two tall blocks 0.04 apart on a floor: from the floor between them none of the directions
  // leaves (the sky is seen only straight up), as from inside the floor; the floor's top faces up,
  // so the crevice is read, not the floor's inside.
  Mesh mesh = test::box({0, 0, 0}, {1, 1, 0.1f});
  test::append(mesh, test::box({0, 0, 0.1f}, {0.48f, 1, 0.9f}));
  test::append(mesh, test::box({0.52f, 0, 0.1f}, {1, 1, 0.9f}));
  const SurfaceScene scene(mesh);
  const SurfaceOpenness crevice = opennessAt(scene, {0.5f, 0.5f, 0.1f});
  EXPECT_FLOAT_EQ(crevice.openness, 0.0f);
  EXPECT_TRUE(std::isinf(crevice.above));
}

TEST(SurfaceOpenness, InsideAClosedBoxNothingLeaves) {
  // A box inside a larger hollow shell: the gap between them is closed all round.
  Mesh mesh = test::box({0.4f, 0.4f, 0.4f}, {0.6f, 0.6f, 0.6f});
  Mesh shell = test::box({0, 0, 0}, {1, 1, 1});
  for (auto& t : shell.triangles) std::swap(t[1], t[2]);
  test::append(mesh, shell);
  const SurfaceScene scene(mesh);
  const SurfaceOpenness inside = opennessAt(scene, {0.5f, 0.5f, 0.6f});
  EXPECT_FLOAT_EQ(inside.openness, 0.0f);
  EXPECT_NEAR(inside.above, 0.4f - kOffset, 1e-4f);
}

}  // namespace
}  // namespace sagrid
