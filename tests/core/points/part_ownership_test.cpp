#include "core/points/part_ownership.h"

#include <gtest/gtest.h>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

constexpr int kResolution = 64;

// A box from centre - below to centre + above for each centre, each a part of its own.
void appendBoxes(Mesh& mesh, const std::vector<Eigen::Vector3f>& centres,
                 const Eigen::Vector3f& below, const Eigen::Vector3f& above) {
  for (const auto& c : centres) test::append(mesh, test::box(c - below, c + above));
}

// A hob in the normalized frame: a grate over the whole top (a large part), two burner caps on
// it, and four knobs in a row on the front edge.
struct Hob {
  std::vector<Eigen::Vector3f> knobs{
      {-0.3f, -0.45f, 0.0f}, {-0.1f, -0.45f, 0.0f}, {0.1f, -0.45f, 0.0f}, {0.3f, -0.45f, 0.0f}};
  std::vector<Eigen::Vector3f> burners{{-0.2f, 0.1f, 0.05f}, {0.2f, 0.1f, 0.05f}};
  std::vector<ConnectedPart> parts;
  Hob() {
    Mesh mesh = test::box({-0.5f, -0.4f, -0.05f}, {0.5f, 0.5f, 0.0f});
    appendBoxes(mesh, burners, {0.06f, 0.06f, 0.05f}, {0.06f, 0.06f, 0.0f});
    appendBoxes(mesh, knobs, {0.02f, 0.02f, 0.02f}, {0.02f, 0.02f, 0.0f});
    parts = connectedParts(mesh);
  }
};

ExtractedPoint at(const Eigen::Vector3f& position, float confidence) {
  ExtractedPoint p;
  p.position = position;
  p.confidence = confidence;
  return p;
}

// Knobs and burner caps are parts of their own; a glass hob's printed zones are not.
TypedPoints knobPoints(std::vector<ExtractedPoint> points) { return {std::move(points), true}; }
TypedPoints burnerPoints(std::vector<ExtractedPoint> points) { return {std::move(points), true}; }
TypedPoints zonePoints(std::vector<ExtractedPoint> points) { return {std::move(points), false}; }

TEST(PartOwnership, ABurnerPointOnAKnobGoesWhenTheKnobPointThereIsSurer) {
  const Hob hob;
  const auto out = ownParts({burnerPoints({at(hob.burners[0], 0.7f), at(hob.knobs[2], 0.4f)}),
                             knobPoints({at(hob.knobs[2], 0.6f), at(hob.knobs[3], 0.5f)})},
                            hob.parts, kResolution);
  ASSERT_EQ(out.size(), 2u);
  ASSERT_EQ(out[0].points.size(), 1u);
  EXPECT_EQ(out[0].points[0].position, hob.burners[0]);
  EXPECT_EQ(out[1].points.size(), 2u);
}

TEST(PartOwnership, TheTypeOfTheSurestPointOwnsThePart) {
  const Hob hob;
  const auto out = ownParts({burnerPoints({at(hob.burners[0], 0.7f)}),
                             knobPoints({at(hob.knobs[0], 0.6f), at(hob.burners[0], 0.5f)})},
                            hob.parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 1u);
  ASSERT_EQ(out[1].points.size(), 1u);
  EXPECT_EQ(out[1].points[0].position, hob.knobs[0]);
}

TEST(PartOwnership, KnobPointsOnTheGrateGoWhenOtherKnobPointsLieOnKnobs) {
  const Hob hob;
  const std::vector<ExtractedPoint> points{at({0.0f, 0.3f, 0.0f}, 0.9f), at(hob.knobs[1], 0.5f),
                                           at({-0.4f, 0.4f, 0.0f}, 0.8f), at(hob.knobs[2], 0.4f)};
  const auto out = ownParts({knobPoints(points)}, hob.parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 2u);
  EXPECT_EQ(out[0].points[0].position, hob.knobs[1]);  // the kept points keep their order
  EXPECT_EQ(out[0].points[1].position, hob.knobs[2]);
  // Points of a type whose instances are not parts of their own stay on the grate.
  const auto zones = ownParts({zonePoints(points)}, hob.parts, kResolution);
  EXPECT_EQ(zones[0].points.size(), 4u);
}

TEST(PartOwnership, BurnerPointsOnTheGrateGoWhenOtherBurnerPointsLieOnCaps) {
  const Hob hob;
  const auto out =
      ownParts({burnerPoints({at({0.0f, 0.3f, 0.0f}, 0.9f), at(hob.burners[1], 0.5f)})}, hob.parts,
               kResolution);
  ASSERT_EQ(out[0].points.size(), 1u);
  EXPECT_EQ(out[0].points[0].position, hob.burners[1]);
}

TEST(PartOwnership, APointNeverMovesOntoAPartAnotherTypeOwns) {
  const Hob hob;
  const Eigen::Vector3f beside = hob.knobs[3] + Eigen::Vector3f(0.0f, 0.06f, 0.02f);
  const auto out = ownParts({burnerPoints({at(hob.burners[0], 0.8f), at(hob.knobs[3], 0.9f)}),
                             knobPoints({at(hob.knobs[0], 0.6f), at(beside, 0.5f)})},
                            hob.parts, kResolution);
  EXPECT_EQ(out[0].points.size(), 2u);  // the surer burner point owns knob 3
  ASSERT_EQ(out[1].points.size(), 1u);
  EXPECT_EQ(out[1].points[0].position, hob.knobs[0]);
}

TEST(PartOwnership, KnobPointsStayWhereNoneLiesOnASmallPart) {
  // One part for the whole object (a merged mesh): nothing to own.
  const auto parts = connectedParts(test::box({-0.5f, -0.5f, -0.1f}, {0.5f, 0.5f, 0.0f}));
  const auto out =
      ownParts({knobPoints({at({0.0f, 0.0f, 0.0f}, 0.5f), at({0.3f, 0.0f, 0.0f}, 0.4f)}),
                burnerPoints({at({0.0f, 0.0f, 0.0f}, 0.9f)})},
               parts, kResolution);
  EXPECT_EQ(out[0].points.size(), 2u);
  EXPECT_EQ(out[1].points.size(), 1u);
}

TEST(PartOwnership, AKnobPointOnTheGrateBesideAFreeKnobMovesOntoIt) {
  const Hob hob;
  // 0.04 behind knob 3's box: more than the 1.5-voxel touch, within the 4-voxel reach.
  const Eigen::Vector3f beside = hob.knobs[3] + Eigen::Vector3f(0.0f, 0.06f, 0.02f);
  const auto out =
      ownParts({knobPoints({at(hob.knobs[0], 0.6f), at(beside, 0.5f)})}, hob.parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 2u);
  EXPECT_LT((out[0].points[1].position - hob.knobs[3]).norm(), 0.02f);
  // Knob 3 already has its point: the point beside it goes.
  const auto taken =
      ownParts({knobPoints({at(hob.knobs[3], 0.6f), at(beside, 0.5f)})}, hob.parts, kResolution);
  EXPECT_EQ(taken[0].points.size(), 1u);
  PartOwnershipSettings noReach;
  noReach.reachVoxels = 0.0f;
  const auto dropped = ownParts({knobPoints({at(hob.knobs[0], 0.6f), at(beside, 0.5f)})}, hob.parts,
                                kResolution, noReach);
  EXPECT_EQ(dropped[0].points.size(), 1u);
}

TEST(PartOwnership, ATypeNeverLosesAllItsPoints) {
  const Hob hob;
  const auto out = ownParts({burnerPoints({at(hob.knobs[0], 0.3f), at(hob.knobs[1], 0.4f)}),
                             knobPoints({at(hob.knobs[0], 0.6f), at(hob.knobs[1], 0.6f)})},
                            hob.parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 1u);
  EXPECT_EQ(out[0].points[0].position, hob.knobs[1]);  // its most confident
  EXPECT_EQ(out[1].points.size(), 2u);
}

TEST(PartOwnership, WithoutPartsOrPointsNothingChanges) {
  const Hob hob;
  const auto out = ownParts({knobPoints({at({0.0f, 0.3f, 0.0f}, 0.9f), at(hob.knobs[1], 0.5f)})},
                            {}, kResolution);
  EXPECT_EQ(out[0].points.size(), 2u);
  EXPECT_TRUE(ownParts({}, hob.parts, kResolution).empty());
  EXPECT_TRUE(ownParts({knobPoints({})}, hob.parts, kResolution)[0].points.empty());
}

// A hot plate in the normalized frame: a slab raised on four small feet, two knobs on its front
// face (their boxes clear of the support plane), burner caps on top.
struct HotPlate {
  std::vector<Eigen::Vector3f> knobs{{-0.3f, -0.22f, 0.06f}, {0.3f, -0.22f, 0.06f}};
  std::vector<Eigen::Vector3f> feet{{-0.45f, -0.15f, -0.01f},
                                    {0.45f, -0.15f, -0.01f},
                                    {-0.45f, 0.15f, -0.01f},
                                    {0.45f, 0.15f, -0.01f}};
  std::vector<ConnectedPart> parts;
  HotPlate() {
    Mesh mesh = test::box({-0.5f, -0.2f, 0.0f}, {0.5f, 0.2f, 0.1f});
    appendBoxes(mesh, knobs, {0.02f, 0.02f, 0.02f}, {0.02f, 0.0f, 0.02f});
    appendBoxes(mesh, feet, {0.02f, 0.02f, 0.01f}, {0.02f, 0.02f, 0.01f});
    parts = connectedParts(mesh);
  }
};

TEST(PartOwnership, KnobPointsOnFeetGoButATypeKeepsItsLastPoint) {
  const HotPlate plate;
  const auto out = ownParts({knobPoints({at(plate.knobs[0], 0.7f), at(plate.feet[0], 0.6f),
                                         at(plate.knobs[1], 0.5f), at(plate.feet[1], 0.4f)})},
                            plate.parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 2u);
  EXPECT_EQ(out[0].points[0].position, plate.knobs[0]);
  EXPECT_EQ(out[0].points[1].position, plate.knobs[1]);
  // Only points on feet: the surest stays.
  const auto onlyFeet = ownParts({knobPoints({at(plate.feet[2], 0.3f), at(plate.feet[3], 0.5f)})},
                                 plate.parts, kResolution);
  ASSERT_EQ(onlyFeet[0].points.size(), 1u);
  EXPECT_EQ(onlyFeet[0].points[0].position, plate.feet[3]);
  // Printed marks are no parts of their own; footHeight 0 switches the rule off.
  EXPECT_EQ(ownParts({zonePoints({at(plate.knobs[0], 0.7f), at(plate.feet[0], 0.6f)})}, plate.parts,
                     kResolution)[0]
                .points.size(),
            2u);
  PartOwnershipSettings off;
  off.footHeight = 0;
  EXPECT_EQ(ownParts({knobPoints({at(plate.knobs[0], 0.7f), at(plate.feet[0], 0.6f)})}, plate.parts,
                     kResolution, off)[0]
                .points.size(),
            2u);
}

TEST(PartOwnership, OnePointPerKnobTheSurestStays) {
  const Hob hob;
  const Eigen::Vector3f besideKnob1 = hob.knobs[1] + Eigen::Vector3f(0.01f, 0.0f, 0.0f);
  const auto out = ownParts({knobPoints({at(hob.knobs[0], 0.7f), at(besideKnob1, 0.4f),
                                         at(hob.knobs[1], 0.6f), at(hob.knobs[2], 0.5f)})},
                            hob.parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 3u);
  EXPECT_EQ(out[0].points[0].position, hob.knobs[0]);
  EXPECT_EQ(out[0].points[1].position, hob.knobs[1]);
  EXPECT_EQ(out[0].points[2].position, hob.knobs[2]);
  // Zones printed on one glass top are no parts of their own; the switch turns the rule off.
  EXPECT_EQ(ownParts({zonePoints({at(hob.knobs[1], 0.6f), at(besideKnob1, 0.4f)})}, hob.parts,
                     kResolution)[0]
                .points.size(),
            2u);
  PartOwnershipSettings off;
  off.onePointPerPart = false;
  EXPECT_EQ(ownParts({knobPoints({at(hob.knobs[1], 0.6f), at(besideKnob1, 0.4f)})}, hob.parts,
                     kResolution, off)[0]
                .points.size(),
            2u);
}

TEST(PartOwnership, AFullRowOfKnobsOwnsItsKnobsOverSurerBurnerPoints) {
  // Knob points on all four knobs; surer burner points on two of them.
  const Hob hob;
  std::vector<ExtractedPoint> knobs;
  for (const auto& k : hob.knobs) knobs.push_back(at(k, 0.2f));
  const auto out = ownParts(
      {burnerPoints({at(hob.burners[0], 0.8f), at(hob.knobs[1], 0.5f), at(hob.knobs[2], 0.5f)}),
       knobPoints(knobs)},
      hob.parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 1u);
  EXPECT_EQ(out[0].points[0].position, hob.burners[0]);
  EXPECT_EQ(out[1].points.size(), 4u);
  // Three of the four: no full row, the surer burner points own their knobs.
  knobs.pop_back();
  const auto partRow = ownParts(
      {burnerPoints({at(hob.burners[0], 0.8f), at(hob.knobs[1], 0.5f), at(hob.knobs[2], 0.5f)}),
       knobPoints(knobs)},
      hob.parts, kResolution);
  EXPECT_EQ(partRow[0].points.size(), 3u);
  EXPECT_EQ(partRow[1].points.size(), 1u);
}

TEST(PartOwnership, AStrayFromAFullRowOfKnobsGoes) {
  // Every knob of the row (0.2 apart) has a point; one more floats 1.4 away (a display at the
  // back), another 0.45 away, within 2.5 spacings of the row.
  const Hob hob;
  const Eigen::Vector3f stray(0.0f, 0.9f, 0.3f), beside(0.75f, -0.45f, 0.0f);
  std::vector<ExtractedPoint> points;
  for (const auto& k : hob.knobs) points.push_back(at(k, 0.6f));
  points.push_back(at(stray, 0.9f));
  points.push_back(at(beside, 0.5f));
  const auto out = ownParts({knobPoints(points)}, hob.parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 5u);
  for (const auto& p : out[0].points) EXPECT_NE(p.position, stray);
  PartOwnershipSettings noRule;
  noRule.strayRowSpacings = 0.0f;
  EXPECT_EQ(ownParts({knobPoints(points)}, hob.parts, kResolution, noRule)[0].points.size(), 6u);
}

TEST(PartOwnership, ARangeWithTwoFullRowsKeepsBoth) {
  // The front row of four knobs (0.2 apart), and three larger oven knobs 0.3 apart at the back,
  // 0.9 from the front row (beyond 2.5 of its spacings): both rows keep their points; a point
  // 1 away from either row goes.
  Hob hob;
  const std::vector<Eigen::Vector3f> ovenKnobs{
      {-0.3f, 0.45f, 0.05f}, {0.0f, 0.45f, 0.05f}, {0.3f, 0.45f, 0.05f}};
  Mesh mesh = test::box({-0.5f, -0.4f, -0.05f}, {0.5f, 0.5f, 0.0f});
  appendBoxes(mesh, hob.knobs, {0.02f, 0.02f, 0.02f}, {0.02f, 0.02f, 0.0f});
  appendBoxes(mesh, ovenKnobs, {0.03f, 0.03f, 0.03f}, {0.03f, 0.03f, 0.0f});
  const auto parts = connectedParts(mesh);
  const Eigen::Vector3f stray(0.9f, 1.2f, 0.3f);
  std::vector<ExtractedPoint> points;
  for (const auto& k : hob.knobs) points.push_back(at(k, 0.6f));
  for (const auto& k : ovenKnobs) points.push_back(at(k, 0.5f));
  points.push_back(at(stray, 0.9f));
  const auto out = ownParts({knobPoints(points)}, parts, kResolution);
  ASSERT_EQ(out[0].points.size(), 7u);
  for (const auto& p : out[0].points) EXPECT_NE(p.position, stray);
}

TEST(PartOwnership, WithoutAFullRowAStrayStays) {
  // Three of the four knobs have a point: the row is not complete, so nothing says the stray is
  // not a knob of another shape.
  const Hob hob;
  const Eigen::Vector3f stray(0.0f, 0.9f, 0.3f);
  const auto out = ownParts({knobPoints({at(hob.knobs[0], 0.6f), at(hob.knobs[1], 0.6f),
                                         at(hob.knobs[2], 0.6f), at(stray, 0.9f)})},
                            hob.parts, kResolution);
  EXPECT_EQ(out[0].points.size(), 4u);
}

}  // namespace
}  // namespace sagrid
