#include "core/annotate/spout_outlet_pass.h"

#include <gtest/gtest.h>

#include "support/analytic_meshes.h"
#include "support/object_under_test.h"

namespace sagrid {
namespace {

// A 60 x 40 cm basin floor with a pillar tap at its back: a 2 cm post up to 20 cm, a handle on
// it, a 7 cm spout forward at 16-18 cm whose outlet is its underside near the tip.
struct BasinWithTap : test::ObjectUnderTest {
  Eigen::Vector3f handleTop{0.0f, 0.16f, 0.22f}, outlet{0.0f, 0.1f, 0.16f};
  BasinWithTap() {
    mesh = test::box({-0.3f, -0.2f, 0.0f}, {0.3f, 0.2f, 0.02f});
    test::append(mesh, test::box({-0.01f, 0.15f, 0.02f}, {0.01f, 0.17f, 0.2f}));
    test::append(mesh, test::box({-0.01f, 0.08f, 0.16f}, {0.01f, 0.15f, 0.18f}));
    test::append(mesh, test::box({-0.02f, 0.15f, 0.2f}, {0.02f, 0.17f, 0.22f}));
    finish();
  }
  // The model's point: on the handle, where its field is lowest; the outlet 0.01 higher.
  ModelPrediction predicted(const std::string& model) const {
    ExtractionSettings oneMinimum;
    oneMinimum.maxDistance = 0.005f;
    return ObjectUnderTest::predicted(model, {handleTop, outlet}, {0.0f, 0.01f}, oneMinimum);
  }
};

TEST(SpoutOutletPass, AFluidSourceOnTheHandleMovesToTheOutletOnTheSurface) {
  const BasinWithTap basin;
  ModelPrediction p = basin.predicted("sink.fluidsource");
  ASSERT_EQ(p.points.size(), 1u);
  ASSERT_LT((p.surface[0].position - basin.handleTop).norm(), 0.02f);
  applySpoutOutlets(p, basin.grid, *basin.scene, UpAxis::Z, ExtractionSettings{});
  ASSERT_EQ(p.points.size(), 1u);
  ASSERT_EQ(p.surface.size(), 1u);
  EXPECT_LT((p.surface[0].position - basin.outlet).norm(), 0.03f);
  EXPECT_NEAR(p.surface[0].position.z(), 0.16f, 0.005f);  // the spout's underside
  EXPECT_LT(basin.scene->closestPoint(p.surface[0].position).distance, 1e-4f);
}

TEST(SpoutOutletPass, LeavesOtherTypesAsTheyAre) {
  const BasinWithTap basin;
  ModelPrediction p = basin.predicted("sink.togglebutton");
  ASSERT_EQ(p.points.size(), 1u);
  const Eigen::Vector3f before = p.surface[0].position;
  applySpoutOutlets(p, basin.grid, *basin.scene, UpAxis::Z, ExtractionSettings{});
  ASSERT_EQ(p.points.size(), 1u);
  EXPECT_EQ(p.surface[0].position, before);
}

}  // namespace
}  // namespace sagrid
