#include "core/eval/count_fitting.h"

#include <gtest/gtest.h>

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
  writeModelsWithFittedCounts(modelsDir, {fit}, root / "fitted");
  const auto card = model::readModelCard(root / "fitted" / "stove.heatsource.json");
  EXPECT_FLOAT_EQ(card.extraction.maxDistance, 0.12f);
  EXPECT_FLOAT_EQ(card.extraction.nmsRadius, 0.25f);
  EXPECT_TRUE(std::filesystem::exists(root / "fitted" / "stove.heatsource.pt"));
  const auto original = model::readModelCard(modelsDir / "stove.heatsource.json");
  EXPECT_NE(original.extraction.maxDistance, 0.12f);
  EXPECT_THROW(writeModelsWithFittedCounts(modelsDir, {fit}, modelsDir), FileError);
}

}  // namespace
}  // namespace sagrid
