#include "core/annotate/repeated_parts_pass.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sagrid
