#include "core/annotate/model_set.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {

// Two large dimensions that vary a lot within each category and two small ones that separate
// the categories: a stove whose large dimensions look like the sink mean.
const std::vector<float> kStoveMean = {100, 50, 1, 0}, kSinkMean = {50, 100, 0, 1};
const std::vector<float> kSpread = {60, 60, 0.1f, 0.1f};
const std::vector<float> kStove = {40, 110, 0.9f, 0.1f};

TEST(ModelSet, RetrievalWeighsDimensionsByTheirSpread) {
  // Plain cosine on the raw descriptor files this stove as a sink ...
  EXPECT_GT(cosineSimilarity(kStove, kSinkMean), cosineSimilarity(kStove, kStoveMean));
  std::vector<model::AffordanceModel> models;
  models.push_back(test::untrainedModelWithDescriptor("stove.heatsource", kStoveMean, kSpread));
  models.push_back(test::untrainedModelWithDescriptor("sink.fluidsource", kSinkMean, kSpread));
  const ModelSet set(std::move(models));
  // ... the standardized similarity does not.
  const auto ranked = set.rankCategories(kStove);
  ASSERT_EQ(ranked.size(), 2u);
  EXPECT_EQ(ranked[0].category, "stove");
  EXPECT_GT(ranked[0].similarity, 0.9);
  EXPECT_LT(ranked[1].similarity, -0.9);
  EXPECT_DOUBLE_EQ(set.categorySimilarity(kStove, "stove"), ranked[0].similarity);
  // A category mean is perfectly similar to itself.
  EXPECT_NEAR(set.categorySimilarity(kSinkMean, "sink"), 1.0, 1e-9);
  EXPECT_THROW(set.categorySimilarity(kStove, "oven"), InvalidArgument);
}

TEST(ModelSet, RetrievalWithoutRecordedSpreadCentresOnly) {
  std::vector<model::AffordanceModel> models;
  models.push_back(test::untrainedModelWithDescriptor("stove.heatsource", {1, 0, 0}, {}));
  models.push_back(test::untrainedModelWithDescriptor("sink.fluidsource", {0, 1, 0}, {}));
  const ModelSet set(std::move(models));
  // Centre (0.5, 0.5, 0): the stove mean is (0.5, -0.5, 0) from there, this descriptor
  // (0.5, 0.5, 7) - centre = (0, 0, 7): orthogonal to both categories.
  EXPECT_NEAR(set.categorySimilarity({0.5f, 0.5f, 7.0f}, "stove"), 0.0, 1e-9);
  EXPECT_NEAR(set.categorySimilarity({1.0f, 0.0f, 0.0f}, "stove"), 1.0, 1e-6);
}

TEST(ModelSet, OneCategoryUsesThePlainCosine) {
  std::vector<model::AffordanceModel> models;
  models.push_back(test::untrainedModelWithDescriptor("stove.heatsource", kStoveMean, kSpread));
  const ModelSet set(std::move(models));
  EXPECT_DOUBLE_EQ(set.categorySimilarity(kStove, "stove"), cosineSimilarity(kStove, kStoveMean));
}

}  // namespace
}  // namespace sagrid
