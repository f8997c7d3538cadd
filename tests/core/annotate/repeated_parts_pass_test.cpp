#include "core/annotate/repeated_parts_pass.h"

#include <gtest/gtest.h>

#include "core/annotate/category_rules.h"
#include "support/analytic_meshes.h"
#include "support/object_under_test.h"

namespace sagrid {
namespace {

// A 60 cm range top with four equal knobs (4 x 3 x 4 cm) in a row on its front, 14 cm apart.
struct RangeWithKnobs : test::ObjectUnderTest {
  std::vector<Eigen::Vector3f> knobs;  // front face centres, mesh frame
  RangeWithKnobs() {
    mesh = test::box({-0.3f, -0.3f, 0.0f}, {0.3f, 0.3f, 0.1f});
    for (float x : {-0.21f, -0.07f, 0.07f, 0.21f}) {
      test::append(mesh, test::box({x - 0.02f, -0.33f, 0.03f}, {x + 0.02f, -0.3f, 0.07f}));
      knobs.emplace_back(x, -0.33f, 0.05f);
    }
    finish();
  }
  // The model's points: only the first knob's minimum is counted.
  ModelPrediction predicted(const std::string& model) const {
    ExtractionSettings oneKnob;
    oneKnob.maxDistance = 0.01f;
    oneKnob.nmsRadius = 0.05f;
    return ObjectUnderTest::predicted(model, knobs, {0.0f, 0.02f, 0.02f, 0.02f}, oneKnob);
  }
};

float nearestSurfacePoint(const ModelPrediction& p, const Eigen::Vector3f& at) {
  float best = 1e9f;
  for (const auto& s : p.surface) best = std::min(best, (s.position - at).norm());
  return best;
}

TEST(RepeatedPartsPass, PutsAPointOnEveryKnobOfTheRowOnTheSurface) {
  const RangeWithKnobs range;
  ModelPrediction p = range.predicted("stove.togglebutton");
  ASSERT_EQ(p.points.size(), 1u);
  const SurfacePoint first = p.surface[0];
  applyRepeatedParts(p, normalizedParts(range.mesh, range.grid.normalization), range.grid,
                     *range.scene, UpAxis::Z, ExtractionSettings{});
  ASSERT_EQ(p.points.size(), 4u);
  ASSERT_EQ(p.surface.size(), 4u);
  EXPECT_EQ(p.surface[0].position, first.position);
  for (const auto& knob : range.knobs) EXPECT_LT(nearestSurfacePoint(p, knob), 0.02f);
  for (const auto& s : p.surface) EXPECT_LT(range.scene->closestPoint(s.position).distance, 1e-4f);
}

TEST(RepeatedPartsPass, LeavesOtherTypesAsTheyAre) {
  const RangeWithKnobs range;
  ModelPrediction p = range.predicted("stove.heatsource");
  ASSERT_EQ(p.points.size(), 1u);
  applyRepeatedParts(p, normalizedParts(range.mesh, range.grid.normalization), range.grid,
                     *range.scene, UpAxis::Z, ExtractionSettings{});
  EXPECT_EQ(p.points.size(), 1u);
  EXPECT_EQ(p.surface.size(), 1u);
}

// A 60 cm hob with four round flat burner caps (8 x 8 x 2 cm) on its top, the last a wok
// burner's (10 x 10 x 2.5 cm).
struct HobWithCaps : test::ObjectUnderTest {
  std::vector<Eigen::Vector3f> caps;  // top centres, mesh frame
  HobWithCaps() {
    mesh = test::box({-0.3f, -0.3f, 0.0f}, {0.3f, 0.3f, 0.1f});
    const std::vector<Eigen::Vector2f> at = {{-0.15f, -0.15f}, {0.15f, -0.15f}, {-0.15f, 0.15f}};
    for (const auto& c : at) {
      test::append(mesh, test::box({c.x() - 0.04f, c.y() - 0.04f, 0.1f},
                                   {c.x() + 0.04f, c.y() + 0.04f, 0.12f}));
      caps.emplace_back(c.x(), c.y(), 0.12f);
    }
    test::append(mesh, test::box({0.1f, 0.1f, 0.1f}, {0.2f, 0.2f, 0.125f}));
    caps.emplace_back(0.15f, 0.15f, 0.125f);
    finish();
  }
};

TEST(RepeatedPartsPass, OnStovesABurnerCapRepeatsOnTheOtherCapsTheWokBurnerToo) {
  const HobWithCaps hob;
  ExtractionSettings oneBurner;
  oneBurner.maxDistance = 0.01f;
  oneBurner.nmsRadius = 0.05f;
  ModelPrediction p =
      hob.predicted("stove.heatsource", hob.caps, {0.0f, 0.02f, 0.02f, 0.02f}, oneBurner);
  ASSERT_EQ(p.points.size(), 1u);
  const auto parts = normalizedParts(hob.mesh, hob.grid.normalization);
  ModelPrediction unchanged = p;
  applyRepeatedParts(unchanged, parts, hob.grid, *hob.scene, UpAxis::Z, ExtractionSettings{});
  EXPECT_EQ(unchanged.points.size(), 1u);
  const RepeatedPartSettings caps = *categoryRulesFor("stove").burnerCaps;
  // A cap that holds a point of another type (a knob point on it) gets none.
  ModelPrediction besideAKnob = p;
  applyRepeatedParts(besideAKnob, parts, hob.grid, *hob.scene, UpAxis::Z, ExtractionSettings{},
                     caps, {hob.grid.normalization.toNormalized(hob.caps[1])});
  EXPECT_EQ(besideAKnob.points.size(), 3u);
  EXPECT_GT(nearestSurfacePoint(besideAKnob, hob.caps[1]), 0.05f);
  applyRepeatedParts(p, parts, hob.grid, *hob.scene, UpAxis::Z, ExtractionSettings{}, caps);
  ASSERT_EQ(p.points.size(), 4u);
  for (const auto& cap : hob.caps) EXPECT_LT(nearestSurfacePoint(p, cap), 0.02f);
}

}  // namespace
}  // namespace sagrid
