#include "core/annotate/printed_marks_pass.h"

#include <gtest/gtest.h>

#include "core/features/feature_grid.h"
#include "core/features/feature_pipeline.h"
#include "core/generate/dataset_generator.h"
#include "core/geometry/surface_scene.h"
#include "support/analytic_meshes.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {

// A 60 x 50 cm glass sheet with two zones and one touch symbol printed on it.
struct Hob {
  Mesh mesh = test::box({-0.3f, -0.25f, 0.0f}, {0.3f, 0.25f, 0.006f});
  PrintedMarks marks;
  Hob() {
    marks.zones = {{{-0.15f, 0.05f, 0.006f}, 0.09f, 1.0f}, {{0.15f, 0.05f, 0.006f}, 0.07f, 0.9f}};
    marks.symbols = {{{0.0f, -0.2f, 0.006f}, 0.008f, 1.0f}};
  }
};

struct Scene {
  Hob hob;
  FeatureGrid grid;
  std::unique_ptr<SurfaceScene> scene;
  Scene() {
    FeatureOptions options;
    options.views = 12;
    grid = computeFeatures(hob.mesh, options);
    scene = std::make_unique<SurfaceScene>(hob.mesh);
  }
  ModelPrediction predicted(const model::AffordanceModel& model, InstanceMode mode) const {
    PredictedField field;
    field.resolution = grid.resolution;
    field.voxels = grid.voxels;
    field.distances.assign(grid.voxels.size(), 0.3f);
    return predictionFromField(model, field, grid, *scene, UpAxis::Z, mode);
  }
};

TEST(PrintedMarksPass, ZonesStandForStoveHeatSourcesAndSymbolsForStoveToggles) {
  const Hob hob;
  EXPECT_EQ(printedMarksFor(hob.marks, "stove", "heatsource").circles.size(), 2u);
  EXPECT_TRUE(printedMarksFor(hob.marks, "stove", "heatsource").replaceModelPoints);
  EXPECT_EQ(printedMarksFor(hob.marks, "stove", "togglebutton").circles.size(), 1u);
  // One symbol is not a touch panel: the model's own toggle points stay beside it.
  EXPECT_FALSE(printedMarksFor(hob.marks, "stove", "togglebutton").replaceModelPoints);
  EXPECT_TRUE(printedMarksFor(hob.marks, "sink", "togglebutton").circles.empty());
  EXPECT_TRUE(printedMarksFor(hob.marks, "stove", "fluidsource").circles.empty());
  PrintedMarks panel = hob.marks;
  panel.symbols.push_back({{0.05f, -0.2f, 0.006f}, 0.008f, 1.0f});
  EXPECT_TRUE(printedMarksFor(panel, "stove", "togglebutton").replaceModelPoints);
  // Symbols without zones (a keypad, lettering on a range with knobs) or a pattern of many
  // circles (fries in a fryer) are not a printed hob.
  PrintedMarks pattern = panel;
  pattern.symbols.assign(25, panel.symbols.front());
  EXPECT_TRUE(printedMarksFor(pattern, "stove", "togglebutton").circles.empty());
  EXPECT_EQ(printedMarksFor(pattern, "stove", "heatsource").circles.size(), 2u);
  pattern.zones.assign(9, panel.zones.front());
  EXPECT_TRUE(printedMarksFor(pattern, "stove", "heatsource").circles.empty());
  panel.zones.clear();
  EXPECT_TRUE(printedMarksFor(panel, "stove", "togglebutton").circles.empty());
}

TEST(PrintedMarksPass, OnlyStovesAreSearched) {
  const Mesh glassHob = gen::makeRawObject("stove", 51, 0, {0.0, 1.0}).mesh;
  EXPECT_FALSE(printedMarksOf(glassHob, "stove").empty());
  EXPECT_TRUE(printedMarksOf(glassHob, "sink").empty());
  EXPECT_TRUE(printedMarksOf(glassHob, "none").empty());
}

TEST(PrintedMarksPass, ZonesReplaceTheHeatSourcePointsAndPullTheFieldToThem) {
  const Scene s;
  const auto model = test::untrainedModelFor("stove.heatsource", s.grid);
  ModelPrediction p = s.predicted(model, InstanceMode::Auto);
  const MarksForType forZones = printedMarksFor(s.hob.marks, "stove", "heatsource");
  const auto& zones = forZones.circles;
  applyPrintedMarks(model, p, forZones, s.grid, *s.scene, UpAxis::Z, InstanceMode::Auto);
  ASSERT_EQ(p.points.size(), 2u);
  ASSERT_EQ(p.surface.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LT((p.surface[i].position - zones[i].centre).norm(), 1e-3f);
    EXPECT_FLOAT_EQ(p.points[i].confidence, zones[i].support);
  }
  // The field: the distance to the nearest zone where that is below the model's 0.3.
  const float voxel = 1.0f / static_cast<float>(s.grid.resolution);
  const auto best = std::min_element(p.field.distances.begin(), p.field.distances.end());
  EXPECT_LT(*best, voxel);
  EXPECT_FLOAT_EQ(*std::max_element(p.field.distances.begin(), p.field.distances.end()), 0.3f);

  // The paper's argmin reads the same field: a zone.
  ModelPrediction single = s.predicted(model, InstanceMode::Single);
  applyPrintedMarks(model, single, forZones, s.grid, *s.scene, UpAxis::Z, InstanceMode::Single);
  ASSERT_EQ(single.surface.size(), 1u);
  const float toZone = std::min((single.surface[0].position - zones[0].centre).norm(),
                                (single.surface[0].position - zones[1].centre).norm());
  EXPECT_LT(toZone, 0.02f);
}

TEST(PrintedMarksPass, SymbolsJoinTheModelsTogglePointsThatLieElsewhere) {
  const Scene s;
  const auto model = test::untrainedModelFor("stove.togglebutton", s.grid);
  ModelPrediction p = s.predicted(model, InstanceMode::Auto);
  const Normalization& n = s.grid.normalization;
  // The model's own points: one on the symbol (dropped for it), one on the far edge (kept).
  p.points = {{n.toNormalized({0.01f, -0.2f, 0.006f}), 0.02f, 0.5f},
              {n.toNormalized({0.29f, 0.2f, 0.006f}), 0.02f, 0.5f}};
  p.surface = {{{0.01f, -0.2f, 0.006f}, Eigen::Vector3f::UnitZ()},
               {{0.29f, 0.2f, 0.006f}, Eigen::Vector3f::UnitZ()}};
  const MarksForType forSymbols = printedMarksFor(s.hob.marks, "stove", "togglebutton");
  const auto& symbols = forSymbols.circles;
  applyPrintedMarks(model, p, forSymbols, s.grid, *s.scene, UpAxis::Z, InstanceMode::Auto);
  ASSERT_EQ(p.surface.size(), 2u);
  EXPECT_LT((p.surface[0].position - symbols[0].centre).norm(), 1e-3f);
  EXPECT_LT((p.surface[1].position - Eigen::Vector3f(0.29f, 0.2f, 0.006f)).norm(), 1e-6f);

  // A touch panel (zones and two or more symbols): the symbols alone.
  PrintedMarks panel = s.hob.marks;
  panel.symbols.push_back({{0.05f, -0.2f, 0.006f}, 0.008f, 1.0f});
  ModelPrediction onPanel = s.predicted(model, InstanceMode::Auto);
  onPanel.points = {{n.toNormalized({0.29f, 0.2f, 0.006f}), 0.02f, 0.5f}};
  onPanel.surface = {{{0.29f, 0.2f, 0.006f}, Eigen::Vector3f::UnitZ()}};
  applyPrintedMarks(model, onPanel, printedMarksFor(panel, "stove", "togglebutton"), s.grid,
                    *s.scene, UpAxis::Z, InstanceMode::Auto);
  ASSERT_EQ(onPanel.surface.size(), 2u);
  for (const auto& p : onPanel.surface) EXPECT_LT(p.position.y(), -0.19f);

  ModelPrediction untouched = s.predicted(model, InstanceMode::Auto);
  const auto before = untouched.field.distances;
  applyPrintedMarks(model, untouched, {}, s.grid, *s.scene, UpAxis::Z, InstanceMode::Auto);
  EXPECT_EQ(untouched.field.distances, before);
}

}  // namespace
}  // namespace sagrid
