#include "core/eval/count_fitting.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/model/model_card.h"
#include "support/synthetic_fields.h"
#include "support/test_paths.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {

using test::onPlate;
using test::plateField;

// Four objects with 1-4 instances whose predicted minima sit at 0.07: above the default
// automatic-count threshold, so the default settings keep only the best minimum.
FieldsWithTruth raisedFields() {
  FieldsWithTruth data;
  const std::vector<std::vector<Eigen::Vector3f>> layouts = {
      {onPlate(16, 16)},
      {onPlate(6, 6), onPlate(6, 25)},
      {onPlate(6, 6), onPlate(25, 6), onPlate(25, 25)},
      {onPlate(6, 6), onPlate(6, 25), onPlate(25, 6), onPlate(25, 25)}};
  for (std::size_t l = 0; l < layouts.size(); ++l) {
    auto f = plateField(layouts[l], 0.003f, 5 + static_cast<unsigned>(l));
    for (auto& d : f.distances) d += 0.07f;
    data.fields.push_back(f);
    data.truths.push_back(layouts[l]);
  }
  return data;
}

ModelSet oneModel() {
  std::vector<model::AffordanceModel> models;
  models.push_back(test::untrainedModelWithDescriptor("stove.heatsource", {0, 1}, {1, 1}));
  return ModelSet(std::move(models));
}

TEST(CountFitting, RefitCountsRightWhereTheCardsSettingsDoNot) {
  const ModelSet models = oneModel();
  EvaluationReport report;
  report.fieldsByModel["stove.heatsource"] = raisedFields();
  const auto fits = fitCounts(models, report);
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_EQ(fits[0].objects, 4u);
  EXPECT_DOUBLE_EQ(fits[0].rightBefore, 0.25);  // only the one-instance object
  EXPECT_DOUBLE_EQ(fits[0].rightAfter, 1.0);
  EXPECT_GT(fits[0].after.maxDistance, 0.07f);
  EXPECT_EQ(fits[0].after.refineVoxels, fits[0].before.refineVoxels);
}

// Two objects with one burner and a spurious minimum at 0.04 far from it, and one with six
// burners whose minima sit at 0.05. Right counts prefer a threshold below 0.04 (two objects right,
// the six-burner one shows one point: 5 additions); the curator's edits prefer one at 0.05 or
// above (six-burner right, two deletions).
TEST(CountFitting, CuratorEditsWeighWhatEachWrongCountCosts) {
  // Two objects with one true minimum and a spurious one 0.045 above it, far away, as deep as a
  // true basin; one object with eight true minima from 0.005 to 0.075. No threshold, basin depth
  // or suppression radius keeps all eight and drops both spurious ones: the right-count objective
  // gives up the eight (two right of three), the edit objective the two (two deletions cost less
  // than the additions on the eight).
  FieldsWithTruth data;
  for (int shift : {0, 2}) {
    const Eigen::Vector3f truth = onPlate(8 + shift, 8), spurious = onPlate(24, 24 - shift);
    data.fields.push_back(test::plateFieldWithOffsets({truth, spurious}, {0.0f, 0.045f}));
    data.truths.push_back({truth});
  }
  std::vector<Eigen::Vector3f> eight;
  std::vector<float> offsets;
  for (int row : {5, 26})
    for (int column : {5, 12, 19, 26}) {
      eight.push_back(onPlate(row, column));
      offsets.push_back(0.005f + 0.01f * static_cast<float>(offsets.size()));
    }
  data.fields.push_back(test::plateFieldWithOffsets(eight, offsets));
  data.truths.push_back(eight);
  data.metresPerUnit = {1.0, 1.0, 1.0};
  EvaluationReport report;
  report.fieldsByModel["stove.heatsource"] = data;

  const auto byCount = fitCounts(oneModel(), report, CountObjective::RightCount);
  ASSERT_EQ(byCount.size(), 1u);
  EXPECT_NEAR(byCount[0].rightAfter, 2.0 / 3.0, 1e-9);

  const auto byEdits = fitCounts(oneModel(), report, CountObjective::CuratorEdits);
  ASSERT_EQ(byEdits.size(), 1u);
  EXPECT_NEAR(byEdits[0].rightAfter, 1.0 / 3.0, 1e-9);
  EXPECT_NEAR(byEdits[0].editsAfter, 2.0 / 3.0, 1e-9);  // the two spurious points deleted
  EXPECT_GT(byCount[0].editsAfter, byEdits[0].editsAfter);

  data.metresPerUnit.clear();  // hand-built fields without scale: edits cannot be weighed
  report.fieldsByModel["stove.heatsource"] = data;
  EXPECT_THROW(fitCounts(oneModel(), report, CountObjective::CuratorEdits), InvalidArgument);
  EXPECT_TRUE(std::isnan(fitCounts(oneModel(), report)[0].editsAfter));
}

TEST(CountFitting, ModelsWithoutKeptFieldsAreNotFitted) {
  EXPECT_TRUE(fitCounts(oneModel(), EvaluationReport{}).empty());
}

TEST(CountFitting, WritesACopiedModelsFolderWithTheRefittedCards) {
  const auto root = test::freshTempDir();
  const auto modelsDir = root / "models";
  std::filesystem::create_directories(modelsDir);
  auto model = test::untrainedModelWithDescriptor("stove.heatsource", {0, 1}, {1, 1});
  model.save(modelsDir / "stove.heatsource.json");
  CountFit fit;
  fit.model = "stove.heatsource";
  fit.after.maxDistance = 0.12f;
  fit.after.nmsRadius = 0.25f;
  fit.after.maxDistanceAboveBest = true;
  fit.after.minPersistence = 0.02f;
  writeModelsWithFittedCounts(modelsDir, {fit}, root / "fitted");
  const auto card = model::readModelCard(root / "fitted" / "stove.heatsource.json");
  EXPECT_FLOAT_EQ(card.extraction.maxDistance, 0.12f);
  EXPECT_FLOAT_EQ(card.extraction.nmsRadius, 0.25f);
  EXPECT_TRUE(card.extraction.maxDistanceAboveBest);
  EXPECT_FLOAT_EQ(card.extraction.minPersistence, 0.02f);
  EXPECT_TRUE(std::filesystem::exists(root / "fitted" / "stove.heatsource.pt"));
  const auto original = model::readModelCard(modelsDir / "stove.heatsource.json");
  EXPECT_NE(original.extraction.maxDistance, 0.12f);
  EXPECT_THROW(writeModelsWithFittedCounts(modelsDir, {fit}, modelsDir), FileError);
}

}  // namespace
}  // namespace sagrid
