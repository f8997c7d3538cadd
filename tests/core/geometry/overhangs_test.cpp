#include "core/geometry/overhangs.h"

#include <gtest/gtest.h>

#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// A 60 x 40 cm basin floor and a pillar tap at its back: a 2 cm post up to 20 cm, a 10 cm spout
// forward from it at 14-16 cm (its underside 12 cm over the floor), a handle on top.
Mesh basinWithTap() {
  Mesh mesh = test::box({-0.3f, -0.2f, 0.0f}, {0.3f, 0.2f, 0.02f});
  test::append(mesh, test::box({-0.01f, 0.15f, 0.02f}, {0.01f, 0.17f, 0.2f}));
  test::append(mesh, test::box({-0.01f, 0.05f, 0.14f}, {0.01f, 0.15f, 0.16f}));
  test::append(mesh, test::box({-0.02f, 0.15f, 0.2f}, {0.02f, 0.17f, 0.22f}));
  return mesh;
}

// Off the lattice's edges: no ray runs along a box's face.
const Eigen::Vector3f kAboveTheTap(0.0025f, 0.1625f, 0.21f);

OverhangSearch searchOf(float radius) {
  OverhangSearch s;
  s.radius = radius;
  s.step = 0.005f;
  s.minDrop = 0.05f;
  s.maxDrop = 0.5f;
  s.minClearance = 0.02f;
  return s;
}

TEST(Overhangs, TheSpoutsUndersideWithItsDropToTheFloor) {
  const SurfaceScene scene(basinWithTap());
  const auto found = overhangsNear(scene, kAboveTheTap, searchOf(0.2f));
  ASSERT_FALSE(found.empty());
  for (const auto& o : found) {
    // Only the spout's underside: the inside of the post and of the handle is no open space.
    EXPECT_NEAR(o.position.z(), 0.14f, 1e-4f);
    EXPECT_GE(o.position.y(), 0.05f - 1e-4f);
    EXPECT_LE(o.position.y(), 0.15f + 1e-4f);
    EXPECT_NEAR(o.drop, 0.12f, 1e-4f);
    EXPECT_GE(o.skyView, 0.5f);
  }
}

TEST(Overhangs, NoneOutsideTheRadiusOrDropRange) {
  const SurfaceScene scene(basinWithTap());
  EXPECT_TRUE(overhangsNear(scene, {0.25f, -0.15f, 0.21f}, searchOf(0.05f)).empty());
  OverhangSearch shortDrops = searchOf(0.2f);
  shortDrops.maxDrop = 0.1f;
  EXPECT_TRUE(overhangsNear(scene, kAboveTheTap, shortDrops).empty());
}

TEST(Overhangs, ACoveredFloorDoesNotSeeTheSky) {
  // A cabinet: floor, a top 30 cm above it on four posts; its top's underside is an overhang over
  // the floor that sees no sky around it.
  Mesh cabinet = test::box({-0.3f, -0.3f, 0.0f}, {0.3f, 0.3f, 0.02f});
  test::append(cabinet, test::box({-0.3f, -0.3f, 0.32f}, {0.3f, 0.3f, 0.34f}));
  for (float x : {-0.3f, 0.28f})
    for (float y : {-0.3f, 0.28f})
      test::append(cabinet, test::box({x, y, 0.02f}, {x + 0.02f, y + 0.02f, 0.32f}));
  const SurfaceScene scene(cabinet);
  const auto found = overhangsNear(scene, {0.0025f, 0.0025f, 0.33f}, searchOf(0.05f));
  ASSERT_FALSE(found.empty());
  for (const auto& o : found) EXPECT_EQ(o.skyView, 0.0f);
}

TEST(Overhangs, NothingForBadSearchSettings) {
  const SurfaceScene scene(basinWithTap());
  OverhangSearch none = searchOf(0.2f);
  none.step = 0;
  EXPECT_TRUE(overhangsNear(scene, kAboveTheTap, none).empty());
  OverhangSearch tooFine = searchOf(0.2f);
  tooFine.step = 1e-5f;  // more rays than the limit
  EXPECT_TRUE(overhangsNear(scene, kAboveTheTap, tooFine).empty());
}

}  // namespace
}  // namespace sagrid
