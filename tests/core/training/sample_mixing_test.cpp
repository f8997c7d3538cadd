#include "core/training/sample_mixing.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/common/error.h"
#include "core/training/training_sources.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

TEST(MixedData, WeightsThreeToOneDrawSeventyFiveAndTwentyFivePercent) {
  // Dataset sizes differ (5 and 20 objects): the weight, not the size, sets the share.
  const auto weights = mixedSampleWeights({5, 20}, {3.0, 1.0});
  ASSERT_EQ(weights.size(), 25u);
  std::mt19937 rng(7);
  std::size_t first = 0, total = 0;
  std::vector<std::size_t> perObject(25, 0);
  for (int epoch = 0; epoch < 400; ++epoch)
    for (std::size_t i : drawEpochOrder(25, weights, rng)) {
      ASSERT_LT(i, 25u);
      first += i < 5;
      ++perObject[i];
      ++total;
    }
  EXPECT_EQ(total, 400u * 25u);  // an epoch is as many draws as all datasets hold objects
  EXPECT_NEAR(static_cast<double>(first) / total, 0.75, 0.01);
  // Uniform within a dataset: 75 % / 5 objects = 15 % each, 25 % / 20 = 1.25 % each.
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(perObject[i] / double(total), 0.15, 0.01);
  for (std::size_t i = 5; i < 25; ++i) EXPECT_NEAR(perObject[i] / double(total), 0.0125, 0.004);
}

TEST(MixedData, SameSeedSameDrawsAndNoWeightsIsAPermutation) {
  const auto weights = mixedSampleWeights({3, 4}, {1.0, 2.0});
  std::mt19937 a(11), b(11);
  EXPECT_EQ(drawEpochOrder(7, weights, a), drawEpochOrder(7, weights, b));
  std::mt19937 rng(3);
  auto order = drawEpochOrder(7, {}, rng);
  std::sort(order.begin(), order.end());
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6}));
}

TEST(MixedData, RejectsMismatchedOrUnusableWeights) {
  EXPECT_THROW(mixedSampleWeights({3}, {1.0, 2.0}), InvalidArgument);
  EXPECT_THROW(mixedSampleWeights({3, 4}, {1.0, -1.0}), InvalidArgument);
  EXPECT_THROW(mixedSampleWeights({0, 4}, {1.0, 0.0}), InvalidArgument);
}

TEST(TrainingSources, ParsesDirectoryAndOptionalWeight) {
  auto s = parseTrainingDataSource("data/real:3");
  EXPECT_EQ(s.dir, "data/real");
  EXPECT_DOUBLE_EQ(s.weight, 3.0);
  EXPECT_EQ(s.role, "data");
  s = parseTrainingDataSource("data/real", "replay");
  EXPECT_EQ(s.dir, "data/real");
  EXPECT_DOUBLE_EQ(s.weight, 1.0);
  EXPECT_EQ(s.role, "replay");
  s = parseTrainingDataSource("C:dir");  // not a number after ':': part of the path
  EXPECT_EQ(s.dir, "C:dir");
  EXPECT_THROW(parseTrainingDataSource("data:0"), InvalidArgument);
  EXPECT_THROW(parseTrainingDataSource("data:-2"), InvalidArgument);
}

TEST(TrainingSources, DefaultPresetTrainsSinkModelsAlsoOnTheDressedSinks) {
  const auto bench = test::freshTempDir("preset-sources");
  const auto stove = defaultTrainingSources(bench, "stove.heatsource");
  ASSERT_EQ(stove.size(), 1u);
  EXPECT_EQ(stove[0].dir, bench / "train");
  EXPECT_TRUE(
      std::filesystem::exists(bench / "train" / "manifest.jsonl"));  // generated when missing
  EXPECT_FALSE(std::filesystem::exists(bench / "wall-fixtures"));
  const auto sink = defaultTrainingSources(bench, "sink.fluidsource");
  ASSERT_EQ(sink.size(), 2u);
  EXPECT_EQ(sink[1].dir, bench / "wall-fixtures");
  EXPECT_TRUE(std::filesystem::exists(bench / "wall-fixtures" / "manifest.jsonl"));
  for (const auto& s : sink) {
    EXPECT_EQ(s.role, "data");
    EXPECT_DOUBLE_EQ(s.weight, 1.0);
    EXPECT_EQ(s.cacheDir, bench / ".sagrid-cache");  // one feature cache for every split
  }
}

}  // namespace
}  // namespace sagrid
