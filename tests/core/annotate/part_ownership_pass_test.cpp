#include "core/annotate/part_ownership_pass.h"

#include <gtest/gtest.h>

#include "core/annotate/repeated_parts_pass.h"
#include "support/analytic_meshes.h"
#include "support/object_under_test.h"

namespace sagrid {
namespace {

// A 60 cm hob: a 16 cm burner cap on its top and a 4 cm knob on its front.
struct HobWithKnob : test::ObjectUnderTest {
  Eigen::Vector3f burner{0.1f, 0.05f, 0.12f}, knob{-0.15f, -0.33f, 0.05f};
  HobWithKnob() {
    mesh = test::box({-0.3f, -0.3f, 0.0f}, {0.3f, 0.3f, 0.1f});
    test::append(mesh, test::box({0.02f, -0.03f, 0.1f}, {0.18f, 0.13f, 0.12f}));
    test::append(mesh, test::box({-0.17f, -0.33f, 0.03f}, {-0.13f, -0.3f, 0.07f}));
    finish();
  }
  ModelPrediction predicted(const std::string& model, const std::vector<Eigen::Vector3f>& centres,
                            const std::vector<float>& offsets) const {
    ExtractionSettings each;
    each.maxDistance = 0.05f;
    each.nmsRadius = 0.05f;
    return ObjectUnderTest::predicted(model, centres, offsets, each);
  }
};

TEST(PartOwnershipPass, ABurnerPointOnTheKnobGoesAndTheOthersKeepTheirSurfacePoints) {
  const HobWithKnob hob;
  std::vector<ModelPrediction> predictions{
      hob.predicted("stove.heatsource", {hob.burner, hob.knob}, {0.0f, 0.02f}),
      hob.predicted("stove.togglebutton", {hob.knob}, {0.0f})};
  ASSERT_EQ(predictions[0].points.size(), 2u);
  ASSERT_EQ(predictions[1].points.size(), 1u);
  const auto burnerSurface = predictions[0].surface[0].position;
  const auto knobSurface = predictions[1].surface[0].position;
  ASSERT_LT((knobSurface - hob.knob).norm(), 0.03f);
  applyPartOwnership(predictions, normalizedParts(hob.mesh, hob.grid.normalization), hob.grid,
                     *hob.scene, UpAxis::Z);
  ASSERT_EQ(predictions[0].points.size(), 1u);
  ASSERT_EQ(predictions[0].surface.size(), 1u);
  EXPECT_EQ(predictions[0].surface[0].position, burnerSurface);
  ASSERT_EQ(predictions[1].surface.size(), 1u);
  EXPECT_EQ(predictions[1].surface[0].position, knobSurface);
}

}  // namespace
}  // namespace sagrid
