// Point candidates of the learned decision: where they come from and what they carry.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/points/point_candidates.h"
#include "support/synthetic_fields.h"

namespace sagrid {
namespace {

using test::onPlate;

float feature(const PointCandidate& c, const std::string& name) {
  const auto& names = candidateFeatureNames();
  return c.features.at(std::find(names.begin(), names.end(), name) - names.begin());
}

const PointCandidate* candidateNear(const std::vector<PointCandidate>& candidates,
                                    const Eigen::Vector3f& p) {
  for (const auto& c : candidates)
    if ((c.position - p).norm() < 1.5f / test::kPlateResolution) return &c;
  return nullptr;
}

SurfaceContact facingUp(const Eigen::Vector3f&) { return {Eigen::Vector3f::UnitZ(), 0.0f}; }

TEST(PointCandidates, TheOtherModelsFieldsSayWhichModelAPlaceBelongsTo) {
  // A knob model's field has two basins, the shallower on a burner: the burner model's field is
  // lowest there and far above its best at the knob.
  const Eigen::Vector3f knob = onPlate(6, 10), burner = onPlate(26, 10);
  const PredictedField knobs = test::plateFieldWithOffsets({knob, burner}, {0.0f, 0.05f});
  const PredictedField burners = test::plateField({burner});
  const auto candidates = pointCandidates(knobs, {}, {}, facingUp, {&burners});
  const PointCandidate* atKnob = candidateNear(candidates, knob);
  const PointCandidate* atBurner = candidateNear(candidates, burner);
  ASSERT_TRUE(atKnob && atBurner);
  const float voxel = 1.0f / test::kPlateResolution;
  EXPECT_NEAR(feature(*atBurner, "other_field"), 0.0f, 2 * voxel / 0.2f);
  // 20 voxels from the burner: capped at 1 (0.2 normalized above the burners' best).
  EXPECT_EQ(feature(*atKnob, "other_field"), 1.0f);
  // The burner's place is the other model's more than this one's; the knob's is this one's.
  EXPECT_LT(feature(*atBurner, "other_claim"), 0.0f);
  EXPECT_GT(feature(*atKnob, "other_claim"), 0.5f);
  EXPECT_NEAR(feature(*atBurner, "other_claim"),
              feature(*atBurner, "other_field") - feature(*atBurner, "distance_above_best") / 0.2f,
              1e-5f);
  // Without other models' fields every candidate reads as far from them.
  for (const auto& c : pointCandidates(knobs, {}, {}, facingUp)) {
    EXPECT_EQ(feature(c, "other_field"), 1.0f);
    EXPECT_GE(feature(c, "other_claim"), 0.0f);
  }
}

TEST(PointCandidates, KeptPointsFieldMinimaAndSmallPartsAreCandidates) {
  // Two basins, the second shallower; the count kept the first; a small part stands elsewhere.
  const Eigen::Vector3f a = onPlate(6, 10), b = onPlate(26, 10), knob = onPlate(16, 24);
  const PredictedField field = test::plateFieldWithOffsets({a, b}, {0.0f, 0.05f});
  ConnectedPart part;
  part.triangles = 24;
  part.centroid = knob;
  part.box = Eigen::AlignedBox3f(knob - Eigen::Vector3f::Constant(0.02f),
                                 knob + Eigen::Vector3f::Constant(0.02f));
  part.spread = Eigen::Vector3f(0.01f, 0.01f, 0.004f);
  const auto candidates =
      pointCandidates(field, {test::pointOnField(field, a)}, {part}, facingUp);

  const PointCandidate* atA = candidateNear(candidates, a);
  const PointCandidate* atB = candidateNear(candidates, b);
  const PointCandidate* atKnob = candidateNear(candidates, knob);
  ASSERT_TRUE(atA && atB && atKnob);
  EXPECT_TRUE(atA->kept);
  EXPECT_FALSE(atB->kept);
  EXPECT_EQ(feature(*atA, "kept"), 1.0f);
  EXPECT_EQ(feature(*atA, "best_kept"), 1.0f);
  EXPECT_EQ(feature(*atA, "field_minimum"), 1.0f);  // the kept point is the first minimum too
  EXPECT_EQ(feature(*atB, "field_minimum"), 1.0f);
  EXPECT_EQ(feature(*atKnob, "part_centroid"), 1.0f);
  EXPECT_EQ(feature(*atKnob, "on_part"), 1.0f);
  EXPECT_EQ(feature(*atA, "on_part"), 0.0f);
  // The better basin has the smaller distance, rank 0; the other is above the best by its offset.
  EXPECT_EQ(feature(*atA, "distance_rank"), 0.0f);
  EXPECT_NEAR(feature(*atB, "distance_above_best"), 0.05f, 1.0f / test::kPlateResolution);
  EXPECT_GT(feature(*atB, "basin_depth"), 0.0f);
  for (const auto& c : candidates) {
    ASSERT_EQ(c.features.size(), candidateFeatureNames().size());
    EXPECT_EQ(feature(c, "facing_up"), 1.0f);
    for (float f : c.features) EXPECT_TRUE(std::isfinite(f));
  }
  // No two candidates within a voxel of each other.
  for (std::size_t i = 0; i < candidates.size(); ++i)
    for (std::size_t j = i + 1; j < candidates.size(); ++j)
      EXPECT_GE((candidates[i].position - candidates[j].position).norm(),
                1.5f / test::kPlateResolution);
}

TEST(PointCandidates, HowOpenTheSurfaceIsWhereEachCandidateMeetsIt) {
  // Left of the middle the surface lies under a shelf 0.1 up (a quarter of the sky left open);
  // right of it, nothing above and 0.8 of free fall below (a spout's tip over its basin).
  const Eigen::Vector3f covered = onPlate(6, 10), open = onPlate(26, 10);
  const PredictedField field = test::plateField({covered, open});
  const float middle = (covered.x() + open.x()) / 2;
  const auto contact = [&](const Eigen::Vector3f& at) {
    SurfaceContact c;
    if (at.x() < middle) {
      c.openness = 0.25f, c.above = 0.1f, c.below = 0;
    } else {
      c.below = 0.8f;
    }
    return c;
  };
  const auto candidates = pointCandidates(field, {}, {}, contact);
  const PointCandidate* atCovered = candidateNear(candidates, covered);
  const PointCandidate* atOpen = candidateNear(candidates, open);
  ASSERT_TRUE(atCovered && atOpen);
  EXPECT_EQ(feature(*atCovered, "openness"), 0.25f);
  EXPECT_NEAR(feature(*atCovered, "clear_above"), 0.1f / 0.5f, 1e-6f);  // in half objects
  EXPECT_EQ(feature(*atCovered, "clear_below"), 0.0f);
  EXPECT_EQ(feature(*atOpen, "openness"), 1.0f);
  EXPECT_EQ(feature(*atOpen, "clear_above"), 1.0f);  // nothing above: capped, finite
  EXPECT_EQ(feature(*atOpen, "clear_below"), 1.0f);  // beyond half the object: capped
}

ConnectedPart knobAt(const Eigen::Vector3f& centre, int triangles = 24) {
  ConnectedPart part;
  part.triangles = triangles;
  part.centroid = centre;
  part.box = Eigen::AlignedBox3f(centre - Eigen::Vector3f::Constant(0.02f),
                                 centre + Eigen::Vector3f::Constant(0.02f));
  part.spread = Eigen::Vector3f(0.01f, 0.01f, 0.004f);
  part.area = 0.003f;
  return part;
}

bool linked(const std::vector<PointCandidate>& candidates, const PointCandidate* from,
            const PointCandidate* to) {
  const auto at = static_cast<std::size_t>(to - candidates.data());
  return std::find(from->copies.begin(), from->copies.end(), at) != from->copies.end();
}

TEST(PointCandidates, ACandidateOnAPartIsLinkedToItsPlaceOnEachCopy) {
  // A row of three equal knobs and an odd one; the field's minimum sits on the first knob's
  // centroid, so every knob's centroid is its place on that knob's copies.
  const Eigen::Vector3f k1 = onPlate(6, 20), k2 = onPlate(14, 20), k3 = onPlate(22, 20),
                        odd = onPlate(16, 6);
  const PredictedField field = test::plateFieldWithOffsets({k1}, {0.0f});
  const std::vector<ConnectedPart> parts = {knobAt(k1), knobAt(k2), knobAt(k3), knobAt(odd, 40)};
  const auto candidates = pointCandidates(field, {test::pointOnField(field, k1)}, parts, facingUp);
  const PointCandidate* at1 = candidateNear(candidates, k1);
  const PointCandidate* at2 = candidateNear(candidates, k2);
  const PointCandidate* at3 = candidateNear(candidates, k3);
  const PointCandidate* atOdd = candidateNear(candidates, odd);
  ASSERT_TRUE(at1 && at2 && at3 && atOdd);
  EXPECT_TRUE(linked(candidates, at1, at2) && linked(candidates, at1, at3));
  EXPECT_TRUE(linked(candidates, at2, at1) && linked(candidates, at3, at2));
  EXPECT_FALSE(linked(candidates, at1, atOdd));
  EXPECT_TRUE(atOdd->copies.empty());  // a part of its own has no copies
  for (std::size_t i = 0; i < candidates.size(); ++i)
    for (std::size_t q : candidates[i].copies) {
      ASSERT_LT(q, candidates.size());
      EXPECT_NE(q, i);
    }
}

TEST(PointCandidates, ACreasePatchIsAPartThatSaysSo) {
  // A burner's ring modelled into the hob: a crease patch (core/geometry/crease_patches.h) where
  // no connected part is; a knob of its own beside it.
  const Eigen::Vector3f ring = onPlate(8, 16), knob = onPlate(24, 16);
  const PredictedField field = test::plateFieldWithOffsets({knob}, {0.0f});
  ConnectedPart patch = knobAt(ring);
  patch.byCrease = true;
  const auto candidates =
      pointCandidates(field, {test::pointOnField(field, knob)}, {knobAt(knob), patch}, facingUp);
  const PointCandidate* atRing = candidateNear(candidates, ring);
  const PointCandidate* atKnob = candidateNear(candidates, knob);
  ASSERT_TRUE(atRing && atKnob);
  EXPECT_EQ(feature(*atRing, "part_centroid"), 1.0f);
  EXPECT_EQ(feature(*atRing, "part_by_crease"), 1.0f);
  EXPECT_EQ(feature(*atKnob, "part_by_crease"), 0.0f);
}

TEST(PointCandidates, AnEmptyFieldHasNone) {
  EXPECT_TRUE(pointCandidates(PredictedField{}, {}, {}, facingUp).empty());
}

}  // namespace
}  // namespace sagrid
