#include "core/points/touch_keys.h"

#include <gtest/gtest.h>

#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

constexpr int kResolution = 64;

// A cooktop in the normalized frame (largest extent 1): a slab 1 wide whose top is at z = 0, on a
// cabinet below, with whatever the test puts on or around it.
struct Cooktop {
  Mesh mesh = test::box({-0.5f, -0.3f, -0.4f}, {0.5f, 0.3f, 0.0f});
  void pad(const Eigen::Vector3f& middle, const Eigen::Vector3f& size) {
    test::append(mesh, test::box(middle - 0.5f * size, middle + 0.5f * size));
  }
  // A key 2 cm wide (1.3 voxels) and 2 mm high standing on the top at (x, y).
  void key(float x, float y) { pad({x, y, 0.001f}, {0.02f, 0.016f, 0.002f}); }
  std::vector<TouchKey> keys() const {
    const Normalization identity;
    const SurfaceScene scene(mesh);
    return findTouchKeys(connectedParts(mesh), scene, identity, kResolution);
  }
};

TEST(TouchKeys, FlatPadsOnTheTopAreKeysAtTheMiddleOfTheirTop) {
  Cooktop hob;
  for (int i = 0; i < 4; ++i) hob.key(-0.3f + 0.2f * i, -0.25f);
  const auto keys = hob.keys();
  ASSERT_EQ(keys.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(keys[i].centre.isApprox(Eigen::Vector3f(-0.3f + 0.2f * i, -0.25f, 0.002f), 1e-4f))
        << keys[i].centre.transpose();
    EXPECT_NEAR(keys[i].radius, 0.01f, 1e-5f);
  }
}

TEST(TouchKeys, ASingleKeyCounts) {
  Cooktop hob;
  hob.key(0.2f, -0.2f);
  EXPECT_EQ(hob.keys().size(), 1u);
}

TEST(TouchKeys, KnobsBarsAndPlatesAreNotKeys) {
  Cooktop hob;
  hob.pad({-0.3f, -0.25f, 0.015f}, {0.03f, 0.03f, 0.03f});    // a knob: as high as wide
  hob.pad({-0.1f, -0.25f, 0.001f}, {0.06f, 0.006f, 0.002f});  // a pointer line: long and narrow
  hob.pad({0.1f, 0.0f, 0.002f}, {0.2f, 0.2f, 0.004f});        // a hot plate: wider than a finger
  hob.pad({0.3f, -0.25f, 0.005f}, {0.02f, 0.02f, 0.01f});     // a stud: higher than half a voxel
  EXPECT_TRUE(hob.keys().empty());
}

TEST(TouchKeys, APadInTheAirIsNoKey) {
  Cooktop hob;
  hob.pad({0.0f, -0.34f, -0.05f}, {0.02f, 0.016f, 0.002f});  // in front of the cabinet
  hob.pad({0.2f, -0.34f, -0.05f}, {0.02f, 0.016f, 0.002f});
  EXPECT_TRUE(hob.keys().empty());
}

TEST(TouchKeys, PadsLowOnTheObjectAreNoKeys) {
  Cooktop hob;
  hob.pad({0.0f, -0.33f, -0.375f}, {1.0f, 0.06f, 0.05f});  // a plinth in front, its top at -0.35
  hob.pad({-0.2f, -0.33f, -0.349f}, {0.02f, 0.016f, 0.002f});
  hob.pad({0.2f, -0.33f, -0.349f}, {0.02f, 0.016f, 0.002f});
  EXPECT_TRUE(hob.keys().empty());
}

TEST(TouchKeys, AKeyNearTheEdgeOfTheTopStillStandsOnIt) {
  Cooktop hob;
  hob.key(0.0f, -0.286f);  // its middle 1.4 cm from the front edge: one of eight rays misses
  hob.key(0.3f, -0.286f);
  EXPECT_EQ(hob.keys().size(), 2u);
}

TEST(TouchKeys, DozensOfPadsAreAPatternNotKeys) {
  Cooktop hob;
  for (int i = 0; i < 30; ++i) hob.key(-0.45f + 0.03f * i, 0.1f);
  EXPECT_TRUE(hob.keys().empty());
}

TEST(TouchKeys, TheNormalizationMapsTheRaysIntoTheMeshFrame) {
  // The same cooktop in centimetres, 2 m off the origin: the parts normalized, the scene not.
  Cooktop hob;
  hob.key(0.0f, -0.2f);
  hob.key(0.2f, -0.2f);
  Mesh big = hob.mesh;
  for (auto& p : big.positions) p = p * 100.0f + Eigen::Vector3f(200.0f, 0.0f, 0.0f);
  const Normalization n = Normalization::fromMesh(big);
  std::vector<ConnectedPart> parts = connectedParts(big);
  for (auto& part : parts)
    part.box = Eigen::AlignedBox3f(n.toNormalized(part.box.min()), n.toNormalized(part.box.max()));
  const SurfaceScene scene(big);
  const auto keys = findTouchKeys(parts, scene, n, kResolution);
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_TRUE(n.toMesh(keys[0].centre).isApprox(Eigen::Vector3f(200.0f, -20.0f, 0.2f), 1e-3f))
      << n.toMesh(keys[0].centre).transpose();
}

}  // namespace
}  // namespace sagrid
