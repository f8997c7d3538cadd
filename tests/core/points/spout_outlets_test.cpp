#include "core/points/spout_outlets.h"

#include <gtest/gtest.h>

#include "support/synthetic_fields.h"

namespace sagrid {
namespace {

using test::onPlate;

const float kVoxel = 1.0f / test::kPlateResolution;

OutletCandidate outletAt(const Eigen::Vector3f& p, float dropVoxels = 8, float sky = 1) {
  return {p, dropVoxels * kVoxel, sky};
}

// The point at plate voxel (10, 10), where the field is lowest, and two outlets near it whose
// field is 0.01 and 0.015 higher.
struct TapOnPlate {
  Eigen::Vector3f handle = onPlate(10, 10), outlet = onPlate(14, 10), other = onPlate(10, 16);
  PredictedField field =
      test::plateFieldWithOffsets({handle, outlet, other}, {0.0f, 0.01f, 0.015f});
  std::vector<ExtractedPoint> moved(const std::vector<OutletCandidate>& candidates,
                                    const SpoutOutletSettings& settings = {}) const {
    return moveToOutlets(field, {test::pointOnField(field, handle)}, {candidates},
                         ExtractionSettings{}, settings);
  }
};

TEST(SpoutOutlets, APointOnNoOverhangMovesToTheOutletWhereTheFieldIsLowest) {
  const TapOnPlate tap;
  const auto out = tap.moved({outletAt(tap.other), outletAt(tap.outlet)});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].position.isApprox(tap.outlet));
  EXPECT_NEAR(out[0].distance, 0.01f, 1e-6f);
  EXPECT_NEAR(out[0].confidence, confidenceOf(0.01f, ExtractionSettings{}), 1e-6f);
}

TEST(SpoutOutlets, APointAtAnOutletStays) {
  const TapOnPlate tap;
  const Eigen::Vector3f under = tap.handle + Eigen::Vector3f(kVoxel, 0, 0);
  const auto out = tap.moved({outletAt(tap.outlet), outletAt(under, 2)});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].position.isApprox(tap.handle));
  // An overhang with less open space below it than onOutletDropVoxels is no outlet.
  EXPECT_TRUE(
      tap.moved({outletAt(tap.outlet), outletAt(under, 1)})[0].position.isApprox(tap.outlet));
}

TEST(SpoutOutlets, NoMoveOntoAHighFieldAShortDropOrACoveredLanding) {
  const TapOnPlate tap;
  SpoutOutletSettings strict;
  strict.maxDistanceAbovePoint = 0.005f;
  EXPECT_TRUE(tap.moved({outletAt(tap.outlet)}, strict)[0].position.isApprox(tap.handle));
  EXPECT_TRUE(tap.moved({outletAt(tap.outlet, 4)})[0].position.isApprox(tap.handle));
  EXPECT_TRUE(tap.moved({outletAt(tap.outlet, 50)})[0].position.isApprox(tap.handle));
  EXPECT_TRUE(tap.moved({outletAt(tap.outlet, 8, 0.25f)})[0].position.isApprox(tap.handle));
  EXPECT_TRUE(tap.moved({})[0].position.isApprox(tap.handle));
}

TEST(SpoutOutlets, TwoPointsMovedOntoOneOutletGiveOne) {
  const TapOnPlate tap;
  const Eigen::Vector3f second = onPlate(12, 8);
  const auto out = moveToOutlets(
      tap.field, {test::pointOnField(tap.field, tap.handle), test::pointOnField(tap.field, second)},
      {{outletAt(tap.outlet)}, {outletAt(tap.outlet)}}, ExtractionSettings{});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].position.isApprox(tap.outlet));
}

TEST(SpoutOutlets, UnchangedWithoutFieldOrWithCandidatesForOtherPoints) {
  const TapOnPlate tap;
  const std::vector<ExtractedPoint> points = {test::pointOnField(tap.field, tap.handle)};
  EXPECT_TRUE(
      moveToOutlets(PredictedField{}, points, {{outletAt(tap.outlet)}}, ExtractionSettings{})[0]
          .position.isApprox(tap.handle));
  EXPECT_TRUE(
      moveToOutlets(tap.field, points, {}, ExtractionSettings{})[0].position.isApprox(tap.handle));
}

}  // namespace
}  // namespace sagrid
