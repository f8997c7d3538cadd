#include "core/annotate/object_confidence.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "core/annotate/annotate.h"
#include "core/common/error.h"
#include "core/model/model_card.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

TEST(ObjectConfidence, SignalIsTheLeastSurePointOfAllPredictions) {
  std::vector<ModelPrediction> predictions(2);
  predictions[0].points.resize(2);
  predictions[0].points[0].distance = 0.01f;
  predictions[0].points[1].distance = 0.03f;
  predictions[1].points.resize(1);
  predictions[1].points[0].distance = 0.02f;
  EXPECT_FLOAT_EQ(static_cast<float>(leastSurePointDistance(predictions)), 0.03f);
  EXPECT_EQ(leastSurePointDistance({}), 0.0);
}

TEST(ObjectConfidence, FitRecoversAKnownLogisticMap) {
  // Outcomes drawn from P(right) = sigmoid(-2 + 4 x), x = exp(-d / 0.02).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 0.08);
  std::uniform_real_distribution<double> coin(0, 1);
  std::vector<double> d;
  std::vector<bool> right;
  for (int i = 0; i < 4000; ++i) {
    d.push_back(u(rng));
    right.push_back(coin(rng) < 1 / (1 + std::exp(-(-2 + 4 * std::exp(-d.back() / 0.02)))));
  }
  const ConfidenceCalibration c = fitConfidence(d, right);
  EXPECT_TRUE(c.fitted);
  EXPECT_NEAR(c.intercept, -2.0, 0.25);
  EXPECT_NEAR(c.slope, 4.0, 0.4);
  ASSERT_EQ(c.measuredConfidence.size(), d.size());
  EXPECT_DOUBLE_EQ(c.measuredConfidence[0], c.probability(d[0]));
  EXPECT_GT(c.probability(0.0), c.probability(0.03));
}

TEST(ObjectConfidence, SeparableDataGivesAFiniteMap) {
  const ConfidenceCalibration c = fitConfidence({0.001, 0.002, 0.05, 0.06}, {true, true, false, false});
  EXPECT_TRUE(std::isfinite(c.intercept) && std::isfinite(c.slope));
  EXPECT_GT(c.probability(0.001), 0.9);
  EXPECT_LT(c.probability(0.06), 0.1);
  EXPECT_THROW(fitConfidence({}, {}), InvalidArgument);
  EXPECT_THROW(fitConfidence({0.1}, {true, false}), InvalidArgument);
}

TEST(ObjectConfidence, FileRoundTripsAndBadFilesAreNamed) {
  const auto dir = test::freshTempDir();
  EXPECT_FALSE(readConfidenceCalibration(dir).fitted);  // absent: uncalibrated
  EXPECT_NEAR(readConfidenceCalibration(dir).probability(0.02), std::exp(-1.0), 1e-9);
  ConfidenceCalibration c;
  c.fitted = true;
  c.intercept = 1.25;
  c.slope = -0.5;
  c.objects = 12;
  c.fittedOn = "real-train";
  writeConfidenceCalibration(dir, c);
  const ConfidenceCalibration back = readConfidenceCalibration(dir);
  EXPECT_TRUE(back.fitted);
  EXPECT_DOUBLE_EQ(back.intercept, 1.25);
  EXPECT_DOUBLE_EQ(back.slope, -0.5);
  EXPECT_EQ(back.objects, 12u);
  std::ofstream(dir / kConfidenceFile) << "{\"schema\": \"sagrid.confidence/1\", \"intercept\": 1";
  try {
    readConfidenceCalibration(dir);
    FAIL() << "truncated file accepted";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(kConfidenceFile), std::string::npos) << e.what();
  }
}

TEST(ObjectConfidence, ACalibrationOfOtherNetworksThanTheCardsIsNotUsed) {
  // A models folder whose networks were retrained but whose confidence.json was not: its figures
  // say nothing of these networks, so it reads as uncalibrated; of the same networks, as fitted.
  const auto dir = test::freshTempDir();
  const auto card = std::filesystem::path(SAGRID_SOURCE_DIR) / "resources" / "models" /
                    "sink.fluidsource.json";
  std::filesystem::copy_file(card, dir / card.filename());
  const std::string weights = model::readModelCard(dir / card.filename()).weightsIdentity();
  ConfidenceCalibration c;
  c.fitted = true;
  c.intercept = 1.25;
  c.slope = -0.5;
  c.networkWeights = {{"sink.fluidsource", weights}};
  writeConfidenceCalibration(dir, c);
  const ConfidenceCalibration same = readConfidenceCalibration(dir);
  EXPECT_TRUE(same.fitted);
  EXPECT_EQ(same.networkWeights, c.networkWeights);
  c.networkWeights = {{"sink.fluidsource", std::string(64, 'a')}};
  writeConfidenceCalibration(dir, c);
  EXPECT_FALSE(readConfidenceCalibration(dir).fitted);
  EXPECT_EQ(modelsOfOtherWeights(c, {{"sink.fluidsource", weights}}),
            std::vector<std::string>{"sink.fluidsource"});
  c.networkWeights = {{"stove.heatsource", weights}};  // a model the folder has no card of
  writeConfidenceCalibration(dir, c);
  EXPECT_FALSE(readConfidenceCalibration(dir).fitted);
  // A card it was not fitted on (a model added to the folder) changes the predictions too.
  c.networkWeights = {{"sink.fluidsource", weights}};
  EXPECT_EQ(modelsOfOtherWeights(c, {{"sink.fluidsource", weights}, {"stove.heatsource", weights}}),
            std::vector<std::string>{"stove.heatsource"});
  // Written on its own (scorer cv's OUT, eval --fit-confidence DIR): no cards, nothing to compare.
  const auto alone = test::freshTempDir("confidence-alone");
  writeConfidenceCalibration(alone, c);
  EXPECT_TRUE(readConfidenceCalibration(alone).fitted);
  // Network weights that are not names to identities: one error naming the file.
  std::ofstream(dir / kConfidenceFile)
      << R"({"schema": "sagrid.confidence/1", "intercept": 1, "slope": 1, "network_weights": [1]})";
  EXPECT_THROW(readConfidenceCalibration(dir), FileError);
}

}  // namespace
}  // namespace sagrid
