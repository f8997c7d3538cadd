#include "core/points/spout_controls.h"

#include <gtest/gtest.h>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"
#include "support/synthetic_fields.h"

namespace sagrid {
namespace {

using test::onPlate;

const float kVoxel = 1.0f / test::kPlateResolution;

// A widespread faucet on the plate of synthetic_fields: a spout column 2 x 2 x 3 voxels at plate
// voxel (16, 16) (a small part) and two equal handles `handleOffset` voxels either side of it.
struct Faucet {
  Eigen::Vector3f spoutTop, left, right;
  std::vector<ConnectedPart> parts;
};
Faucet widespreadFaucet(int handleOffset = 4) {
  Faucet f;
  const Eigen::Vector3f foot = onPlate(16, 16);
  Mesh mesh =
      test::box(foot - Eigen::Vector3f(1, 1, 0) * kVoxel, foot + Eigen::Vector3f(1, 1, 3) * kVoxel);
  f.spoutTop = foot + Eigen::Vector3f(0, 0, 3) * kVoxel;
  f.left = onPlate(16 - handleOffset, 16);
  f.right = onPlate(16 + handleOffset, 16);
  for (const auto& h : {f.left, f.right}) {
    const Eigen::Vector3f half = Eigen::Vector3f(1.0f, 0.5f, 0.5f) * kVoxel;
    test::append(mesh, test::box(h - half, h + half));
  }
  f.parts = connectedParts(mesh);
  return f;
}

SpoutControlSettings on() {
  SpoutControlSettings settings;
  settings.reachVoxels = 10.0f;
  return settings;
}

std::vector<ExtractedPoint> fromPoint(const PredictedField& field, const Eigen::Vector3f& at,
                                      const Faucet& faucet, const SpoutControlSettings& settings,
                                      const std::vector<Eigen::Vector3f>& spouts) {
  return movePointsOffSpouts(field, {test::pointOnField(field, at)}, spouts, faucet.parts,
                             ExtractionSettings{}, settings);
}

TEST(SpoutControls, AToggleOnTheSpoutMovesToTheHandleWhereTheFieldIsLowest) {
  const Faucet faucet = widespreadFaucet();
  const Eigen::Vector3f onSpout = onPlate(16, 16);
  for (const bool leftLower : {true, false}) {
    const auto field =
        test::plateFieldWithOffsets({onSpout, faucet.left, faucet.right},
                                    {0.0f, leftLower ? 0.01f : 0.02f, leftLower ? 0.02f : 0.01f});
    const auto out = fromPoint(field, onSpout, faucet, on(), {faucet.spoutTop});
    ASSERT_EQ(out.size(), 1u);
    const Eigen::Vector3f expected = leftLower ? faucet.left : faucet.right;
    EXPECT_TRUE(out[0].position.isApprox(expected, 1e-5f)) << out[0].position.transpose();
    EXPECT_NEAR(out[0].distance, 0.01f, 1e-5f);
    EXPECT_GT(out[0].confidence, 0.0f);
    EXPECT_LE(out[0].confidence, 1.0f);
  }
}

TEST(SpoutControls, APointMovedOntoAHandleThatHasOneAlreadyIsDropped) {
  const Faucet faucet = widespreadFaucet();
  const Eigen::Vector3f onSpout = onPlate(16, 16);
  const auto field =
      test::plateFieldWithOffsets({onSpout, faucet.left, faucet.right}, {0.0f, 0.01f, 0.02f});
  // The spout's point moves to the left handle, where the second point already is.
  const std::vector<ExtractedPoint> points = {test::pointOnField(field, onSpout),
                                              test::pointOnField(field, faucet.left)};
  const auto out = movePointsOffSpouts(field, points, {faucet.spoutTop}, faucet.parts,
                                       ExtractionSettings{}, on());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].position.isApprox(faucet.left));
}

TEST(SpoutControls, PointsOffTheSpoutAndObjectsWithoutSpoutsAreLeftAsTheyAre) {
  const Faucet faucet = widespreadFaucet();
  const auto field = test::plateFieldWithOffsets({onPlate(16, 16), faucet.left, faucet.right},
                                                 {0.0f, 0.01f, 0.01f});
  // On a handle already.
  const auto onHandle = fromPoint(field, faucet.left, faucet, on(), {faucet.spoutTop});
  ASSERT_EQ(onHandle.size(), 1u);
  EXPECT_TRUE(onHandle[0].position.isApprox(faucet.left));
  // On the spout, but no fluid-source point on it (the spout is elsewhere), none at all, or off.
  for (const auto& spouts : std::vector<std::vector<Eigen::Vector3f>>{{onPlate(4, 4)}, {}}) {
    const auto kept = fromPoint(field, onPlate(16, 16), faucet, on(), spouts);
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_TRUE(kept[0].position.isApprox(onPlate(16, 16)));
  }
  const auto off = fromPoint(field, onPlate(16, 16), faucet, {}, {faucet.spoutTop});
  EXPECT_TRUE(off[0].position.isApprox(onPlate(16, 16)));
}

TEST(SpoutControls, NoMoveWhereTheHandlesFieldIsHighOrTheyAreOutOfReach) {
  const Eigen::Vector3f onSpout = onPlate(16, 16);
  const Faucet near = widespreadFaucet();
  // The network sees no control at the handles: their field 0.2 above the point's.
  const auto high =
      test::plateFieldWithOffsets({onSpout, near.left, near.right}, {0.0f, 0.2f, 0.2f});
  EXPECT_TRUE(fromPoint(high, onSpout, near, on(), {near.spoutTop})[0].position.isApprox(onSpout));
  SpoutControlSettings anyField = on();
  anyField.maxDistanceAbovePoint = -1.0f;
  EXPECT_FALSE(
      fromPoint(high, onSpout, near, anyField, {near.spoutTop})[0].position.isApprox(onSpout));
  // Handles 12 voxels away, beyond a reach of 10.
  const Faucet far = widespreadFaucet(13);
  const auto field =
      test::plateFieldWithOffsets({onSpout, far.left, far.right}, {0.0f, 0.01f, 0.01f});
  EXPECT_TRUE(fromPoint(field, onSpout, far, on(), {far.spoutTop})[0].position.isApprox(onSpout));
}

}  // namespace
}  // namespace sagrid
