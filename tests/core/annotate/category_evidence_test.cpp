// The affordance-evidence gate after the category classifier: the threshold that keeps a share of
// a category's objects, the gate on a decision, its record in category.json (round trip, sha,
// malformed values) and a model set with other weights switching it off.
#include "core/annotate/category_evidence.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "support/category_samples.h"
#include "support/test_paths.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {

TEST(EvidenceThreshold, KeepsTheAskedShareOfTheObjects) {
  const std::vector<double> evidence = {0.9, 0.0, 0.5, 0.3, 0.8, 0.7, 0.6, 0.2, 0.4, 0.1};
  EXPECT_DOUBLE_EQ(evidenceThresholdKeeping(evidence, 1.0), 0.0);   // keeps every object
  EXPECT_DOUBLE_EQ(evidenceThresholdKeeping(evidence, 0.9), 0.1);   // the lowest goes
  EXPECT_DOUBLE_EQ(evidenceThresholdKeeping(evidence, 0.75), 0.2);  // 8 of 10 kept (>= 7.5)
  EXPECT_DOUBLE_EQ(evidenceThresholdKeeping(evidence, 0.1), 0.9);
  EXPECT_THROW(evidenceThresholdKeeping({}, 0.9), InvalidArgument);
  EXPECT_THROW(evidenceThresholdKeeping(evidence, 0.0), InvalidArgument);
  EXPECT_THROW(evidenceThresholdKeeping(evidence, 1.5), InvalidArgument);
}

TEST(EvidenceGate, RejectsAnAcceptedCategoryWhoseModelsFindTooLittle) {
  EvidenceGate gate;
  gate.thresholds["sink"] = 0.05;
  CategoryDecision sink;
  sink.category = sink.best = "sink";
  sink.score = 0.9;
  int asked = 0;
  auto evidence = [&asked](double value) {
    return [&asked, value](const std::string&) { return ++asked, value; };
  };
  const auto rejected = applyEvidenceGate(sink, gate, evidence(0.01));
  EXPECT_TRUE(rejected.rejected);
  EXPECT_EQ(rejected.category, kRejectedCategory);
  EXPECT_EQ(rejected.best, "sink");  // what a curator may pick
  EXPECT_DOUBLE_EQ(rejected.score, 0.9);
  EXPECT_EQ(applyEvidenceGate(sink, gate, evidence(0.05)).category, "sink");
  EXPECT_EQ(asked, 2);
  // A category without a threshold, and an object the classifier rejected already: the models
  // are not asked.
  CategoryDecision stove = sink;
  stove.category = stove.best = "stove";
  EXPECT_EQ(applyEvidenceGate(stove, gate, evidence(0.0)).category, "stove");
  CategoryDecision none = sink;
  none.rejected = true;
  none.category = kRejectedCategory;
  EXPECT_TRUE(applyEvidenceGate(none, gate, evidence(1.0)).rejected);
  EXPECT_EQ(asked, 2);
}

TEST(EvidenceGate, ADecisionTheClassifierIsSureOfIsNotCheckedByTheModels) {
  EvidenceGate gate;
  gate.thresholds["sink"] = 0.05;
  gate.sureProbability = 0.95;
  CategoryDecision sink;
  sink.category = sink.best = "sink";
  int asked = 0;
  auto noEvidence = [&asked](const std::string&) { return ++asked, 0.0; };
  sink.score = 0.97;  // a standalone faucet the sink models are unsure of: kept unasked
  EXPECT_EQ(applyEvidenceGate(sink, gate, noEvidence).category, "sink");
  EXPECT_EQ(asked, 0);
  sink.score = 0.95;  // at the ceiling: sure
  EXPECT_EQ(applyEvidenceGate(sink, gate, noEvidence).category, "sink");
  EXPECT_EQ(asked, 0);
  sink.score = 0.86;  // a washing machine's drum filed as a basin: asked, and rejected
  EXPECT_TRUE(applyEvidenceGate(sink, gate, noEvidence).rejected);
  EXPECT_EQ(asked, 1);
  EXPECT_TRUE(gate.asks(0.94));
  EXPECT_FALSE(gate.asks(0.95));
  gate.sureProbability.reset();  // unset: every decision is checked
  EXPECT_TRUE(gate.asks(1.0));
}

TEST(EvidenceGate, BestPointConfidenceOfThePredictions) {
  std::vector<ModelPrediction> predictions(2);
  EXPECT_DOUBLE_EQ(affordanceEvidence(predictions), 0.0);  // no points: no evidence
  predictions[0].points.resize(2);
  predictions[0].points[0].confidence = 0.25f;
  predictions[0].points[1].confidence = 0.5f;
  predictions[1].points.resize(1);
  predictions[1].points[0].confidence = 0.125f;
  EXPECT_DOUBLE_EQ(affordanceEvidence(predictions), 0.5);
}

ModelSet stoveAndSinkModels() {
  std::vector<model::AffordanceModel> models;
  for (const char* name : {"stove.heatsource", "stove.togglebutton", "sink.fluidsource"})
    models.push_back(test::untrainedModelWithDescriptor(name, {1, 0, 0}, {1, 1, 1}));
  return ModelSet(std::move(models));
}

CategoryClassifier tinyClassifier() {
  std::vector<CategorySample> samples;
  for (int i = 0; i < 6; ++i) {
    const char* category = i % 3 == 0 ? "stove" : i % 3 == 1 ? "sink" : "none";
    samples.push_back(test::categorySample("s" + std::to_string(i), category, "",
                                           {float(i % 3), float(i), 1.0f}));
  }
  auto c = CategoryClassifier::train(samples, {});
  c.featureBackend = "embedded";
  return c;
}

TEST(EvidenceGate, FittedPerCategoryWithTheWeightsOfItsModels) {
  const ModelSet models = stoveAndSinkModels();
  const auto gate =
      fitEvidenceGate({{"sink", {0.0, 0.2, 0.4, 0.6}}, {"stove", {0.5, 0.7}}}, 0.75, models);
  EXPECT_DOUBLE_EQ(gate.thresholds.at("sink"), 0.2);
  EXPECT_DOUBLE_EQ(gate.thresholds.at("stove"), 0.5);  // 1 of 2 would be less than 75 %
  EXPECT_EQ(gate.modelShas.size(), 3u);                // both stove models and the sink model
  EXPECT_EQ(gate.modelShas.at("sink.fluidsource"),
            models.forCategory("sink").front()->card().weightsSha256);
  EXPECT_THROW(fitEvidenceGate({{"microwave", {0.5}}}, 0.9, models), InvalidArgument);
  EXPECT_THROW(fitEvidenceGate({{"sink", {}}}, 0.9, models), InvalidArgument);
}

TEST(EvidenceGate, SavedInCategoryJsonUnderItsSha) {
  const ModelSet models = stoveAndSinkModels();
  auto c = tinyClassifier();
  c.evidence = fitEvidenceGate({{"sink", {0.1, 0.3}}}, 1.0, models);
  const auto file = test::freshTempDir() / kCategoryClassifierFile;
  c.save(file);
  const auto back = CategoryClassifier::load(file);
  EXPECT_DOUBLE_EQ(back.evidence.thresholds.at("sink"), 0.1);
  EXPECT_EQ(back.evidence.modelShas, c.evidence.modelShas);
  EXPECT_EQ(back.evidence.record.at("keep"), 1.0);
  EXPECT_FALSE(back.evidence.sureProbability);  // none saved: every decision is checked
  c.evidence.sureProbability = 0.95;
  c.save(file);
  EXPECT_DOUBLE_EQ(CategoryClassifier::load(file).evidence.sureProbability.value_or(0), 0.95);
  // A hand-lowered threshold breaks the file's sha.
  auto j = nlohmann::json::parse(readFileBytes(file));
  j["evidence"]["thresholds"]["sink"] = 0.0;
  writeFileAtomic(file, j.dump());
  EXPECT_THROW(CategoryClassifier::load(file), FileError);
  // A threshold that is no confidence: named in the error.
  auto bad = tinyClassifier();
  bad.evidence.thresholds["sink"] = 1.5;
  bad.save(file);
  try {
    CategoryClassifier::load(file);
    FAIL() << "an evidence threshold of 1.5 loaded";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("evidence threshold of \"sink\""), std::string::npos)
        << e.what();
  }
  // A ceiling that is no probability: named in the error.
  bad = tinyClassifier();
  bad.evidence = fitEvidenceGate({{"sink", {0.1, 0.3}}}, 1.0, models);
  bad.evidence.sureProbability = 0.0;
  bad.save(file);
  try {
    CategoryClassifier::load(file);
    FAIL() << "an evidence sure_probability of 0 loaded";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("sure_probability"), std::string::npos) << e.what();
  }
}

TEST(EvidenceGate, AModelSetWithOtherWeightsSwitchesItOff) {
  ModelSet models = stoveAndSinkModels();
  auto c = tinyClassifier();
  c.evidence = fitEvidenceGate({{"sink", {0.1, 0.3}}}, 1.0, models);
  models.setCategoryClassifier(c, "category.json");
  EXPECT_FALSE(models.categoryClassifier()->evidence.empty());
  c.evidence.modelShas["sink.fluidsource"] = std::string(64, '0');  // retrained since
  models.setCategoryClassifier(c, "category.json");
  EXPECT_TRUE(models.categoryClassifier()->evidence.empty());
}

}  // namespace
}  // namespace sagrid
