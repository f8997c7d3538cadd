#include "core/annotate/mirror_pairs_pass.h"

#include <gtest/gtest.h>

#include "core/features/feature_grid.h"
#include "core/features/feature_pipeline.h"
#include "core/geometry/surface_scene.h"
#include "support/analytic_meshes.h"
#include "support/object_under_test.h"
#include "support/synthetic_fields.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {

// A 1 m double-basin counter with a tap at x = -0.3 and one at x = +0.3 (4 x 4 x 20 cm).
struct Counter : test::ObjectUnderTest {
  Eigen::Vector3f left{-0.3f, 0.0f, 0.25f}, right{0.3f, 0.0f, 0.25f};  // tap tops, mesh frame
  Counter() {
    mesh = test::box({-0.5f, -0.3f, 0.0f}, {0.5f, 0.3f, 0.05f});
    test::append(mesh, test::box({-0.32f, -0.02f, 0.05f}, {-0.28f, 0.02f, 0.25f}));
    test::append(mesh, test::box({0.28f, -0.02f, 0.05f}, {0.32f, 0.02f, 0.25f}));
    finish();
  }
  // Field: distance to the left tap's top, and to the right one's plus `rightOffset`.
  PredictedField field(float rightOffset) const {
    return test::fieldTowards(grid, {left, right}, {0.0f, rightOffset});
  }
};

TEST(MirrorPairsPass, AddsTheTwinTapOnTheSurfaceAndKeepsTheModelsPoint) {
  const Counter c;
  const auto model = test::untrainedModelFor("sink.fluidsource", c.grid);
  ExtractionSettings oneTap;
  oneTap.maxDistance = 0.02f;  // the right tap's minimum (0.03 higher) is not counted
  oneTap.nmsRadius = 0.08f;
  ModelPrediction p = predictionFromField(model, c.field(0.03f), c.grid, *c.scene, UpAxis::Z,
                                          InstanceMode::Auto, 1, &oneTap);
  ASSERT_EQ(p.points.size(), 1u);
  const SurfacePoint first = p.surface[0];
  applyMirrorPairs(p, c.grid, *c.scene, UpAxis::Z, oneTap);
  ASSERT_EQ(p.points.size(), 2u);
  ASSERT_EQ(p.surface.size(), 2u);
  EXPECT_EQ(p.surface[0].position, first.position);
  EXPECT_LT((p.surface[0].position - c.left).norm(), 0.03f);
  EXPECT_LT((p.surface[1].position - c.right).norm(), 0.03f);

  // Switched off by the field: the right tap predicted far away.
  ModelPrediction far = predictionFromField(model, c.field(0.3f), c.grid, *c.scene, UpAxis::Z,
                                            InstanceMode::Auto, 1, &oneTap);
  applyMirrorPairs(far, c.grid, *c.scene, UpAxis::Z, oneTap);
  EXPECT_EQ(far.points.size(), 1u);
}

TEST(MirrorPairsPass, PairsTapHandlesAcrossTheSpoutPredictedBefore) {
  // A mixer at x = -0.3 on a 1 m counter: a spout column and a handle 8 cm either side of it.
  Mesh mesh = test::box({-0.5f, -0.3f, 0.0f}, {0.5f, 0.3f, 0.05f});
  test::append(mesh, test::box({-0.32f, -0.02f, 0.05f}, {-0.28f, 0.02f, 0.3f}));
  const Eigen::Vector3f left{-0.38f, 0.0f, 0.2f}, right{-0.22f, 0.0f, 0.2f};  // handle tops
  test::append(mesh, test::box({-0.40f, -0.02f, 0.05f}, {-0.36f, 0.02f, 0.2f}));
  test::append(mesh, test::box({-0.24f, -0.02f, 0.05f}, {-0.20f, 0.02f, 0.2f}));
  FeatureOptions options;
  options.views = 12;
  const FeatureGrid grid = computeFeatures(mesh, options);
  const SurfaceScene scene(mesh);
  const PredictedField field = test::fieldTowards(grid, {left, right}, {0.0f, 0.03f});
  const auto model = test::untrainedModelFor("sink.togglebutton", grid);
  ExtractionSettings oneHandle;
  oneHandle.maxDistance = 0.02f;
  oneHandle.nmsRadius = 0.3f;  // the card's radius keeps the handles (0.16 apart) as one
  const ModelPrediction handles =
      predictionFromField(model, field, grid, scene, UpAxis::Z, InstanceMode::Auto, 1, &oneHandle);
  ASSERT_EQ(handles.points.size(), 1u);
  ModelPrediction spout;
  spout.type = "fluidsource";
  ExtractedPoint top;
  top.position = grid.normalization.toNormalized(Eigen::Vector3f(-0.3f, 0.0f, 0.3f));
  spout.points.push_back(top);

  ModelPrediction withoutSpout = handles;
  applyMirrorPairs(withoutSpout, grid, scene, UpAxis::Z, oneHandle);
  EXPECT_EQ(withoutSpout.points.size(), 1u);
  ModelPrediction paired = handles;
  const auto anchors = mirrorAnchors({spout}, paired.type);
  ASSERT_EQ(anchors.size(), 1u);
  EXPECT_EQ(anchors.front(), top.position);
  applyMirrorPairs(paired, grid, scene, UpAxis::Z, oneHandle, anchors);
  ASSERT_EQ(paired.points.size(), 2u);
  EXPECT_LT((paired.surface[0].position - left).norm(), 0.03f);
  EXPECT_LT((paired.surface[1].position - right).norm(), 0.03f);
  // Spouts anchor toggle buttons only.
  ModelPrediction notToggles = handles;
  notToggles.type = "heatsource";
  EXPECT_TRUE(mirrorAnchors({spout}, notToggles.type).empty());
  applyMirrorPairs(notToggles, grid, scene, UpAxis::Z, oneHandle,
                   mirrorAnchors({spout}, notToggles.type));
  EXPECT_EQ(notToggles.points.size(), 1u);
}

}  // namespace
}  // namespace sagrid
