#include "core/points/repeated_parts.h"

#include <gtest/gtest.h>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"
#include "support/synthetic_fields.h"

namespace sagrid {
namespace {

using test::onPlate;

const float kVoxel = 1.0f / test::kPlateResolution;

// Knobs in a row on the plate of synthetic_fields (j = 16, every 6 voxels from i = 6): boxes of
// 2 x 1 x 1 voxels around the plate voxel's centre, and a panel (a large part) behind them.
std::vector<Eigen::Vector3f> knobRow() {
  return {onPlate(6, 16), onPlate(12, 16), onPlate(18, 16), onPlate(24, 16)};
}

Mesh knobBox(const Eigen::Vector3f& centre, const Eigen::Vector3f& halfSides) {
  return test::box(centre - halfSides, centre + halfSides);
}

std::vector<ConnectedPart> panelWithKnobs(const std::vector<Eigen::Vector3f>& knobs) {
  Mesh mesh = knobBox(onPlate(16, 24), Eigen::Vector3f(0.4f, 0.05f, 0.1f));
  for (const auto& k : knobs)
    test::append(mesh, knobBox(k, Eigen::Vector3f(1.0f, 0.5f, 0.5f) * kVoxel));
  return connectedParts(mesh);
}

// The pass from one point (`at`, normalized frame) with the default extraction settings.
std::vector<ExtractedPoint> fromPoint(const PredictedField& field, const Eigen::Vector3f& at,
                                      const std::vector<ConnectedPart>& parts,
                                      const RepeatedPartSettings& settings = {}) {
  return completeRepeatedParts(field, {test::pointOnField(field, at)}, parts, ExtractionSettings{},
                               settings);
}

TEST(RepeatedParts, AKnobGivesAPointOnEveryCopyInTheRow) {
  const auto knobs = knobRow();
  const auto field = test::plateFieldWithOffsets(knobs, {0.0f, 0.01f, 0.02f, 0.03f});
  const auto out = fromPoint(field, knobs[1], panelWithKnobs(knobs));
  ASSERT_EQ(out.size(), 4u);
  EXPECT_TRUE(out[0].position.isApprox(knobs[1]));
  for (const auto& k : knobs) EXPECT_LT(test::nearestExtracted(out, k), 1e-4f);
  for (std::size_t i = 1; i < out.size(); ++i) {
    EXPECT_GT(out[i].confidence, 0.0f);
    EXPECT_LE(out[i].confidence, 1.0f);
  }
}

TEST(RepeatedParts, NoPointOnACopyWhereTheFieldIsHigh) {
  const auto knobs = knobRow();
  const auto field = test::plateFieldWithOffsets(knobs, {0.0f, 0.0f, 0.0f, 0.2f});
  const auto out = fromPoint(field, knobs[0], panelWithKnobs(knobs));
  EXPECT_EQ(out.size(), 3u);
  EXPECT_GT(test::nearestExtracted(out, knobs[3]), 3 * kVoxel);
  RepeatedPartSettings anyField;
  anyField.maxDistanceAbovePoint = -1.0f;
  EXPECT_EQ(fromPoint(field, knobs[0], panelWithKnobs(knobs), anyField).size(), 4u);
}

TEST(RepeatedParts, ACopyThatHasAPointGetsNoSecond) {
  const auto knobs = knobRow();
  const auto field = test::plateField(knobs);
  // The second point a little off its knob's centre, still on it.
  const Eigen::Vector3f offKnob = knobs[2] + Eigen::Vector3f(0.5f * kVoxel, 0, 0);
  const auto out = completeRepeatedParts(
      field, {test::pointOnField(field, knobs[0]), test::pointOnField(field, offKnob)},
      panelWithKnobs(knobs), ExtractionSettings{});
  EXPECT_EQ(out.size(), 4u);
}

TEST(RepeatedParts, NoPointOnACopyWithinTheSuppressionRadius) {
  // The knobs are 6 voxels (0.19) apart: a suppression radius of 0.25 takes them for parts of
  // one instance (like the spokes of a cross handle), 0.15 for instances of their own.
  const auto knobs = knobRow();
  const auto field = test::plateField(knobs);
  ExtractionSettings wide;
  wide.nmsRadius = 0.25f;
  EXPECT_EQ(completeRepeatedParts(field, {test::pointOnField(field, knobs[0])},
                                  panelWithKnobs(knobs), wide)
                .size(),
            2u);  // only the last knob is 0.56 away
  wide.nmsRadius = 0.15f;
  EXPECT_EQ(completeRepeatedParts(field, {test::pointOnField(field, knobs[0])},
                                  panelWithKnobs(knobs), wide)
                .size(),
            4u);
}

TEST(RepeatedParts, BySpacingKnobsCloserThanTheSuppressionRadiusAllGetPoints) {
  // Points on every other knob of the row, 6 voxels (0.19) apart, with a suppression radius of
  // 0.25: the knobs between are within the radius of a point, but farther than 0.75 of their
  // spacing from it.
  const auto knobs = knobRow();
  const auto field = test::plateField(knobs);
  ExtractionSettings wide;
  wide.nmsRadius = 0.25f;
  const std::vector<ExtractedPoint> everyOther{test::pointOnField(field, knobs[0]),
                                               test::pointOnField(field, knobs[2])};
  const auto parts = panelWithKnobs(knobs);
  EXPECT_EQ(completeRepeatedParts(field, everyOther, parts, wide).size(), 2u);
  RepeatedPartSettings bySpacing;
  bySpacing.separationBySpacing = true;
  const auto out = completeRepeatedParts(field, everyOther, parts, wide, bySpacing);
  ASSERT_EQ(out.size(), 4u);
  for (const auto& k : knobs) EXPECT_LT(test::nearestExtracted(out, k), 1e-4f);
  // A copy with a point on it still gets no second one.
  EXPECT_EQ(completeRepeatedParts(field, out, parts, wide, bySpacing).size(), 4u);
}

TEST(RepeatedParts, TheTrianglesOfASoupAreNoInstances) {
  // 20 000 equal single triangles over the plate (a triangle soup, as some scans and STL exports
  // are): each is a part and a copy of all the others, but too simple to be a knob.
  Mesh soup;
  for (int t = 0; t < 20000; ++t) {
    const Eigen::Vector3f at = onPlate(t % 32, (t / 32) % 32) +
                               Eigen::Vector3f(0, 0, 0.001f * static_cast<float>(t / 1024));
    const int base = static_cast<int>(soup.positions.size());
    soup.positions.push_back(at);
    soup.positions.push_back(at + Eigen::Vector3f(0.2f * kVoxel, 0, 0));
    soup.positions.push_back(at + Eigen::Vector3f(0, 0.2f * kVoxel, 0));
    soup.triangles.emplace_back(base, base + 1, base + 2);
  }
  const auto parts = connectedParts(soup);
  ASSERT_EQ(parts.size(), 20000u);
  const auto field = test::plateField({onPlate(16, 16)});
  EXPECT_EQ(fromPoint(field, onPlate(16, 16), parts).size(), 1u);
}

TEST(RepeatedParts, NothingIsAddedFromALargePartOrAPartWithoutCopies) {
  const auto knobs = knobRow();
  const auto field = test::plateField(knobs);
  const auto parts = panelWithKnobs(knobs);
  // On the panel, far from the knobs.
  const auto onPanel = test::pointOnField(field, onPlate(16, 24));
  EXPECT_EQ(completeRepeatedParts(field, {onPanel}, parts, ExtractionSettings{}).size(), 1u);
  // One knob larger than the others: no copy of it.
  Mesh mesh = knobBox(knobs[0], Eigen::Vector3f(1.5f, 0.5f, 0.5f) * kVoxel);
  for (std::size_t k = 1; k < knobs.size(); ++k)
    test::append(mesh, knobBox(knobs[k], Eigen::Vector3f(1.0f, 0.5f, 0.5f) * kVoxel));
  EXPECT_EQ(fromPoint(field, knobs[0], connectedParts(mesh)).size(), 1u);
  EXPECT_EQ(fromPoint(field, knobs[0], {}).size(), 1u);
}

TEST(RepeatedParts, ATurnedCopyMirrorsThePointAcrossThePlaneBetweenThem) {
  // Two handles either side of a spout, the right one turned a quarter about z: the point on the
  // left handle's inner end (towards the spout) goes to the right handle's inner end.
  const Eigen::Vector3f left = onPlate(10, 16), right = onPlate(20, 16);
  Mesh mesh = knobBox(left, Eigen::Vector3f(2.0f, 1.0f, 0.5f) * kVoxel);
  test::append(mesh, knobBox(right, Eigen::Vector3f(1.0f, 2.0f, 0.5f) * kVoxel));
  const auto field = test::plateField({left, right});
  const Eigen::Vector3f innerEnd = left + Eigen::Vector3f(1.5f * kVoxel, 0, 0);
  const auto out = fromPoint(field, innerEnd, connectedParts(mesh));
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(out[1].position.isApprox(right - Eigen::Vector3f(1.5f * kVoxel, 0, 0), 1e-5f));
}

// A tight row of knobs, 3 voxels apart (2 voxels wide, 1 voxel between them).
std::vector<Eigen::Vector3f> tightKnobRow() {
  return {onPlate(6, 16), onPlate(9, 16), onPlate(12, 16), onPlate(15, 16)};
}

RepeatedPartSettings knobSnapping() {
  RepeatedPartSettings settings;
  settings.separationBySpacing = true;
  settings.snapPartVoxels = 1.0f;
  return settings;
}

TEST(RepeatedParts, SnappedAPointBetweenTwoKnobsMovesOntoTheNearerAndTheRowFills) {
  const auto knobs = tightKnobRow();
  const auto field = test::plateField(knobs);
  const auto parts = panelWithKnobs(knobs);
  // Between the first two knobs, nearer the first, touching both.
  const Eigen::Vector3f between = knobs[0] + Eigen::Vector3f(1.4f * kVoxel, 0, 0);
  const auto out = fromPoint(field, between, parts, knobSnapping());
  ASSERT_EQ(out.size(), 4u);
  EXPECT_TRUE(out[0].position.isApprox(knobs[0], 1e-5f));
  for (const auto& k : knobs) EXPECT_LT(test::nearestExtracted(out, k), 1e-4f);
  // Without snapping the point stays between them, and the copies keep its offset.
  RepeatedPartSettings bySpacing;
  bySpacing.separationBySpacing = true;
  const auto kept = fromPoint(field, between, parts, bySpacing);
  EXPECT_TRUE(kept[0].position.isApprox(between));
  EXPECT_GT(test::nearestExtracted(kept, knobs[3]), 0.5f * kVoxel);
}

TEST(RepeatedParts, SnappedAPointBesideARowOfKnobsMovesOntoTheNearestWithinReach) {
  const auto knobs = tightKnobRow();
  const auto field = test::plateField(knobs);
  const auto parts = panelWithKnobs(knobs);
  // 4 voxels beside the third knob (3.5 from its box), on no small part.
  const auto out = fromPoint(field, onPlate(12, 20), parts, knobSnapping());
  ASSERT_EQ(out.size(), 4u);
  EXPECT_TRUE(out[0].position.isApprox(knobs[2], 1e-5f));
  for (const auto& k : knobs) EXPECT_LT(test::nearestExtracted(out, k), 1e-4f);
  // Out of reach (8 voxels), or without snapping, it stays alone.
  EXPECT_EQ(fromPoint(field, onPlate(12, 24), parts, knobSnapping()).size(), 1u);
  RepeatedPartSettings bySpacing;
  bySpacing.separationBySpacing = true;
  EXPECT_EQ(fromPoint(field, onPlate(12, 20), parts, bySpacing).size(), 1u);
}

TEST(RepeatedParts, ASureKnobRowTakesAPointBesideItWhateverTheField) {
  // The field's valley is at the point, 4 voxels beside the third knob; at the knobs it is 0.1
  // higher, more than maxDistanceAbovePoint (0.05) allows.
  const auto knobs = tightKnobRow();
  const Eigen::Vector3f beside = onPlate(12, 20);
  const auto field = test::plateFieldWithOffsets({beside, knobs[0], knobs[1], knobs[2], knobs[3]},
                                                 {0.0f, 0.1f, 0.1f, 0.1f, 0.1f});
  const auto parts = panelWithKnobs(knobs);
  const auto stays = fromPoint(field, beside, parts, knobSnapping());
  ASSERT_EQ(stays.size(), 1u);
  EXPECT_TRUE(stays[0].position.isApprox(beside));
  RepeatedPartSettings sure = knobSnapping();
  sure.sureKnobRow = 3;
  const auto moved = fromPoint(field, beside, parts, sure);
  ASSERT_FALSE(moved.empty());
  EXPECT_TRUE(moved[0].position.isApprox(knobs[2], 1e-5f));
  // A row of four is not sure enough where five are asked for, and out of reach nothing moves.
  sure.sureKnobRow = 5;
  EXPECT_TRUE(fromPoint(field, beside, parts, sure)[0].position.isApprox(beside));
  sure.sureKnobRow = 3;
  const Eigen::Vector3f far = onPlate(12, 24);
  EXPECT_TRUE(fromPoint(field, far, parts, sure)[0].position.isApprox(far));
}

TEST(RepeatedParts, ALargerKnobContinuingASureRowGetsAPointWhateverTheField) {
  // A row of four knobs every 3 voxels, then a knob 1.25 times larger 5 voxels beyond the last
  // (a range's oven knob): the field there is 0.2 higher than at the row.
  const auto knobs = tightKnobRow();
  const Eigen::Vector3f oven = onPlate(20, 16);
  const auto field = test::plateFieldWithOffsets({knobs[0], knobs[1], knobs[2], knobs[3], oven},
                                                 {0.0f, 0.0f, 0.0f, 0.0f, 0.2f});
  const auto withOvenKnobAt = [&](const Eigen::Vector3f& at) {
    Mesh mesh = knobBox(onPlate(16, 24), Eigen::Vector3f(0.4f, 0.05f, 0.1f));
    for (const auto& k : knobs)
      test::append(mesh, knobBox(k, Eigen::Vector3f(1.0f, 0.5f, 0.5f) * kVoxel));
    test::append(mesh, knobBox(at, 1.25f * Eigen::Vector3f(1.0f, 0.5f, 0.5f) * kVoxel));
    return connectedParts(mesh);
  };
  RepeatedPartSettings sure = knobSnapping();
  sure.sureKnobRow = 3;
  sure.rowContinuationScale = 1.5f;
  const auto out = fromPoint(field, knobs[0], withOvenKnobAt(oven), sure);
  ASSERT_EQ(out.size(), 5u);
  EXPECT_LT(test::nearestExtracted(out, oven), 1e-4f);
  // Off: the row alone. Off the row's line, too far beyond it, or beside a row too short to be
  // sure: no point either.
  RepeatedPartSettings off = sure;
  off.rowContinuationScale = 1.0f;
  EXPECT_EQ(fromPoint(field, knobs[0], withOvenKnobAt(oven), off).size(), 4u);
  EXPECT_EQ(fromPoint(field, knobs[0], withOvenKnobAt(onPlate(20, 20)), sure).size(), 4u);
  EXPECT_EQ(fromPoint(field, knobs[0], withOvenKnobAt(onPlate(24, 16)), sure).size(), 4u);
  RepeatedPartSettings longer = sure;
  longer.sureKnobRow = 5;
  EXPECT_EQ(fromPoint(field, knobs[0], withOvenKnobAt(oven), longer).size(), 4u);
}

// Burner caps (round, flat: 2 x 2 x 0.5 voxels) in a row, the last one a wok burner's (scaled
// 1.3), and grate bars (6 x 0.5 x 0.5 voxels, copies of one another) beside them.
std::vector<ConnectedPart> capsAndBars(const std::vector<Eigen::Vector3f>& caps,
                                       const std::vector<Eigen::Vector3f>& bars) {
  Mesh mesh = knobBox(onPlate(16, 28), Eigen::Vector3f(0.4f, 0.05f, 0.1f));
  for (std::size_t c = 0; c < caps.size(); ++c) {
    const float scale = c + 1 == caps.size() ? 1.3f : 1.0f;
    test::append(mesh, knobBox(caps[c], scale * Eigen::Vector3f(1.0f, 1.0f, 0.25f) * kVoxel));
  }
  for (const auto& b : bars)
    test::append(mesh, knobBox(b, Eigen::Vector3f(3.0f, 0.25f, 0.25f) * kVoxel));
  return connectedParts(mesh);
}

TEST(RepeatedParts, RoundFlatCapsRepeatOnTheirCopiesAndScaledCopiesGrateBarsDoNot) {
  const std::vector<Eigen::Vector3f> caps = {onPlate(6, 8), onPlate(14, 8), onPlate(22, 8)};
  const std::vector<Eigen::Vector3f> bars = {onPlate(8, 20), onPlate(16, 20), onPlate(24, 20)};
  const auto parts = capsAndBars(caps, bars);
  RepeatedPartSettings burners;
  burners.roundFlatSeeds = true;
  burners.maxCopyScale = 1.5f;
  // From the first cap: the second cap and the wok burner's cap.
  const auto fromCap = fromPoint(test::plateField(caps), caps[0], parts, burners);
  ASSERT_EQ(fromCap.size(), 3u);
  for (const auto& c : caps) EXPECT_LT(test::nearestExtracted(fromCap, c), 1e-4f);
  // Congruent copies only: the wok burner gets no point.
  RepeatedPartSettings congruent = burners;
  congruent.maxCopyScale = 1.0f;
  EXPECT_EQ(fromPoint(test::plateField(caps), caps[0], parts, congruent).size(), 2u);
  // A point on a grate bar repeats on nothing; without roundFlatSeeds on every bar.
  EXPECT_EQ(fromPoint(test::plateField(bars), bars[0], parts, burners).size(), 1u);
  EXPECT_EQ(fromPoint(test::plateField(bars), bars[0], parts).size(), 3u);
}

TEST(RepeatedParts, SnappedPartsUnderAVoxelAreNoKnobs) {
  // A row of indicator lights half a voxel across: a point beside them stays where it is, and
  // the copies keep the floor of separationVoxels.
  const auto lights = tightKnobRow();
  Mesh mesh = knobBox(onPlate(16, 24), Eigen::Vector3f(0.4f, 0.05f, 0.1f));
  for (const auto& l : lights)
    test::append(mesh, knobBox(l, Eigen::Vector3f(0.25f, 0.25f, 0.25f) * kVoxel));
  const auto field = test::plateField(lights);
  const auto out = fromPoint(field, onPlate(12, 20), connectedParts(mesh), knobSnapping());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].position.isApprox(test::pointOnField(field, onPlate(12, 20)).position));
}

// A mixer on a counter: a spout (a column taller than a small part may be) with two equal handles
// 5 voxels either side of it, and `extra` more handles further along when given.
std::vector<ConnectedPart> mixer(const std::vector<Eigen::Vector3f>& handles) {
  Mesh mesh = test::box(onPlate(16, 16) - Eigen::Vector3f(1, 1, 0) * kVoxel,
                        onPlate(16, 16) + Eigen::Vector3f(1, 1, 8) * kVoxel);
  for (const auto& h : handles)
    test::append(mesh, knobBox(h, Eigen::Vector3f(1.0f, 0.5f, 0.5f) * kVoxel));
  return connectedParts(mesh);
}

TEST(RepeatedParts, APointAtTheSpoutMovesOntoTheNearerOfTwoEqualHandlesAndPairsIt) {
  const Eigen::Vector3f left = onPlate(11, 16), right = onPlate(21, 16);
  const auto field =
      test::plateFieldWithOffsets({onPlate(15, 16), left, right}, {0.0f, 0.01f, 0.01f});
  // Predicted at the spout's foot, a voxel to its left.
  const auto out = fromPoint(field, onPlate(15, 16), mixer({left, right}));
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(out[0].position.isApprox(left, 1e-5f));
  EXPECT_TRUE(out[1].position.isApprox(right, 1e-5f));
  // Off: the point stays where it was.
  RepeatedPartSettings stay;
  stay.pairReachVoxels = 0;
  const auto kept = fromPoint(field, onPlate(15, 16), mixer({left, right}), stay);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_TRUE(kept[0].position.isApprox(onPlate(15, 16)));
}

TEST(RepeatedParts, NoMoveOntoPartsThatAreMoreThanAPairOrOutOfReach) {
  const Eigen::Vector3f left = onPlate(11, 16), right = onPlate(21, 16);
  const auto field = test::plateField({onPlate(15, 16), left, right});
  const auto atSpout = test::pointOnField(field, onPlate(15, 16));
  // Four equal parts: a row of something else, not a hot and a cold handle.
  EXPECT_EQ(
      completeRepeatedParts(field, {atSpout}, mixer({left, right, onPlate(5, 16), onPlate(27, 16)}),
                            ExtractionSettings{})
          .size(),
      1u);
  // The pair 10 voxels away.
  EXPECT_EQ(completeRepeatedParts(field, {atSpout}, mixer({onPlate(4, 16), onPlate(28, 16)}),
                                  ExtractionSettings{})
                .size(),
            1u);
}

}  // namespace
}  // namespace sagrid
