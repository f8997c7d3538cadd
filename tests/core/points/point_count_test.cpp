// The learned count of points: the object's description under the first look, trees that learn
// how many points objects have, and the choice growing while the next point is worth its risk.
#include "core/points/point_count.h"

#include <gtest/gtest.h>

#include <random>

#include "core/common/error.h"
#include "core/points/candidate_classifier.h"

namespace sagrid {
namespace {

PointCandidate candidateAt(float x, bool kept = false) {
  return {Eigen::Vector3f(x, 0, 0), 0.0f, kept, {x}};
}

TEST(PointCount, TheFeaturesDescribeTheRankingUnderTheFirstLook) {
  std::vector<PointCandidate> c = {candidateAt(0.0f, true), candidateAt(0.02f), candidateAt(0.3f),
                                   candidateAt(0.6f)};
  c[0].copies = {2};
  // 1 lies within the radius of the better 0: not in the ranking (0, 2, 3).
  const auto x = countFeatures(c, {0.9f, 0.8f, 0.4f, 0.1f}, 0.05f);
  // The other models' four and k follow in the trees' rows.
  ASSERT_EQ(x.size() + 5, countFeatureNames().size());
  EXPECT_EQ(countFeatureNames().back(), "k");
  const std::vector<float> expected = {1, 4, 0.9f, 0.4f, 0.1f, 0, 0, 0, 0, 0, 1.4f, 1, 2, 2, 2};
  ASSERT_EQ(x.size(), expected.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    EXPECT_NEAR(x[i], expected[i], 1e-5f) << countFeatureNames()[i];
  EXPECT_THROW(countFeatures(c, {0.5f}, 0.05f), InvalidArgument);
  const auto rows = countRows(x);
  ASSERT_EQ(rows.size(), kMaxLearnedCount);
  EXPECT_EQ(rows[2].back(), 3.0f);
}

// The object's other models of the category: their count's number of points, probabilities'
// sum and likely and possible points, summed; zeros where there are none.
TEST(PointCount, TheOtherModelsOfTheCategoryAddTheirCountsSummed) {
  const std::vector<PointCandidate> c = {candidateAt(0.0f, true), candidateAt(0.3f)};
  const auto own = countFeatures(c, {0.9f, 0.3f}, 0.05f);
  const auto alone = withOtherModels(own, {});
  ASSERT_EQ(alone.size() + 1, countFeatureNames().size());
  for (std::size_t i = own.size(); i < alone.size(); ++i) EXPECT_EQ(alone[i], 0.0f);
  const auto other = countFeatures(c, {0.6f, 0.2f}, 0.05f);
  const auto both = withOtherModels(own, {own, other});
  const std::size_t at = own.size();
  EXPECT_EQ(countFeatureNames()[at], "other_models_kept_count");
  EXPECT_NEAR(both[at], 2.0f, 1e-6f);      // one kept point each
  EXPECT_NEAR(both[at + 1], 2.0f, 1e-6f);  // p_sum 1.2 + 0.8
  EXPECT_NEAR(both[at + 2], 2.0f, 1e-6f);  // 0.9 and 0.6 at least 0.5
  EXPECT_NEAR(both[at + 3], 3.0f, 1e-6f);  // and 0.3 at least 0.25
  for (std::size_t i = 0; i < at; ++i) EXPECT_EQ(both[i], own[i]);
  EXPECT_THROW(withOtherModels({1.0f}, {}), InvalidArgument);
  EXPECT_THROW(withOtherModels(own, {{1.0f}}), InvalidArgument);
}

// How many points the trees give the object: the k at which P(k or more) is at least a half.
std::size_t mostLikelyCount(const BoostedTrees& trees, const std::vector<float>& x) {
  std::size_t n = 0;
  for (std::size_t k = 1; k <= kMaxLearnedCount; ++k) n += countAtLeast(trees, x, k) >= 0.5f;
  return n;
}

// Trees that say: two points or more, surely; three or more, surely not.
BoostedTrees twoPoints() {
  BoostedTrees t;
  t.features = countFeatureNames().size();
  const int k = static_cast<int>(t.features) - 1;
  t.trees.push_back({{k, 2.5f, 1, 2, 0.0f}, {-1, 0, -1, -1, 5.0f}, {-1, 0, -1, -1, -5.0f}});
  return t;
}

TEST(PointCount, AChoiceGrowsWhileTheNextPointIsWorthItsRisk) {
  const BoostedTrees trees = twoPoints();
  const std::vector<float> x(countFeatureNames().size() - 1, 0.0f);
  EXPECT_EQ(mostLikelyCount(trees, x), 2u);
  EXPECT_GT(countAtLeast(trees, x, 2), 0.99f);
  EXPECT_LT(countAtLeast(trees, x, 3), 0.01f);
  EXPECT_EQ(countAtLeast(trees, x, 0), 1.0f);
  EXPECT_EQ(countAtLeast(trees, x, kMaxLearnedCount + 1), 0.0f);

  const std::vector<PointCandidate> c = {candidateAt(0.0f), candidateAt(0.01f), candidateAt(0.6f),
                                         candidateAt(0.3f), candidateAt(0.9f)};
  const std::vector<float> p = {0.9f, 0.5f, 0.05f, 0.3f, 0.2f};
  const std::vector<std::size_t> ranking = {0, 1, 3, 4, 2};
  // 1 lies beside the taken 0; 3 joins (0.3 with a second point sure); 4 would be a third.
  EXPECT_EQ(withLearnedCount({0}, ranking, p, c, 0.05f, trees, x),
            (std::vector<std::size_t>{0, 3}));
  // What the choice took stays, however many.
  EXPECT_EQ(withLearnedCount({0, 4, 2}, ranking, p, c, 0.05f, trees, x),
            (std::vector<std::size_t>{0, 4, 2}));
  // A candidate no better than the doubt about the count does not join.
  const std::vector<float> unsure = {0.9f, 0.5f, 0.005f, 0.005f, 0.005f};
  EXPECT_EQ(withLearnedCount({0}, ranking, unsure, c, 0.05f, trees, x),
            (std::vector<std::size_t>{0}));
}

// An object of `points` points among 8 candidates: the first look marks them (0.6 - 1, the
// others 0 - 0.4).
std::vector<float> describedObject(std::size_t points, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<PointCandidate> c;
  std::vector<float> firstLook;
  for (std::size_t i = 0; i < 8; ++i) {
    c.push_back(candidateAt(0.3f * static_cast<float>(i), u(rng) < 0.3f));
    firstLook.push_back(i < points ? 0.6f + 0.4f * u(rng) : 0.4f * u(rng));
  }
  return withOtherModels(countFeatures(c, firstLook, 0.05f), {});
}

TEST(PointCount, FittedTreesLearnHowManyPointsObjectsHave) {
  std::mt19937 rng(3);
  std::vector<std::vector<float>> rows;
  std::vector<bool> positive;
  for (int object = 0; object < 200; ++object) {
    const std::size_t points = 1 + object % 5;
    const auto objectRows = countRows(describedObject(points, rng));
    for (std::size_t k = 0; k < objectRows.size(); ++k) {
      rows.push_back(objectRows[k]);
      positive.push_back(points > k);
    }
  }
  BoostingOptions options;
  options.monotone.assign(countFeatureNames().size(), 0);
  options.monotone.back() = -1;
  const BoostedTrees trees =
      fitBoostedTrees(rows, positive, std::vector<float>(rows.size(), 1.0f), options);
  int right = 0;
  for (int object = 0; object < 50; ++object) {
    const std::size_t points = 1 + object % 5;
    const auto x = describedObject(points, rng);
    right += mostLikelyCount(trees, x) == points;
    for (std::size_t k = 1; k < kMaxLearnedCount; ++k)
      EXPECT_GE(countAtLeast(trees, x, k), countAtLeast(trees, x, k + 1));
  }
  EXPECT_GE(right, 45);
}

}  // namespace
}  // namespace sagrid
