// The learned point decision's classifiers (logistic regression, boosted trees) and its choice
// among candidates: known labels on synthetic candidates.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "core/common/error.h"
#include "core/points/boosted_trees.h"
#include "core/points/candidate_classifier.h"

namespace sagrid {
namespace {

// Rows of two features in [0, 1]; positive where `rule` says.
struct Rows {
  std::vector<std::vector<float>> x;
  std::vector<bool> y;
  std::vector<float> w;
};
template <class Rule>
Rows rowsBy(Rule rule, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Rows r;
  for (int i = 0; i < n; ++i) {
    const float a = u(rng), b = u(rng);
    r.x.push_back({a, b});
    r.y.push_back(rule(a, b));
    r.w.push_back(1.0f);
  }
  return r;
}

template <class Score>
double accuracy(const Rows& r, Score score) {
  int right = 0;
  for (std::size_t i = 0; i < r.x.size(); ++i) right += (score(r.x[i]) >= 0.5) == r.y[i];
  return static_cast<double>(right) / r.x.size();
}

TEST(CandidateClassifier, TheLogisticRegressionLearnsALinearRule) {
  auto rule = [](float a, float b) { return a + 2 * b > 1.4f; };
  const Rows train = rowsBy(rule, 600, 1), test = rowsBy(rule, 400, 2);
  const CandidateClassifier c = fitCandidateClassifier(train.x, train.y, train.w, 0.01);
  EXPECT_GT(accuracy(test, [&](const auto& x) { return c.probability(x); }), 0.95);
  EXPECT_THROW(c.probability({0.5f}), InvalidArgument);
}

TEST(CandidateClassifier, BoostedTreesLearnWhatNoLineSeparates) {
  // A checkerboard of two cells per side: no linear rule beats chance.
  auto rule = [](float a, float b) { return (a < 0.5f) != (b < 0.5f); };
  const Rows train = rowsBy(rule, 800, 3), test = rowsBy(rule, 400, 4);
  const BoostedTrees trees = fitBoostedTrees(train.x, train.y, train.w);
  auto treeProbability = [&](const auto& x) { return 1.0 / (1.0 + std::exp(-trees.score(x))); };
  EXPECT_GT(accuracy(test, treeProbability), 0.95);
  const CandidateClassifier line = fitCandidateClassifier(train.x, train.y, train.w);
  EXPECT_LT(accuracy(test, [&](const auto& x) { return line.probability(x); }), 0.7);
  // Saved (7 significant digits) and read back: the same scores.
  const BoostedTrees again = boostedTreesFromJson(toJson(trees));
  for (const auto& x : test.x) EXPECT_NEAR(again.score(x), trees.score(x), 1e-5f);
}

// Positive at both ends of the first feature: free trees score the far end high again; with the
// first feature monotone (never rising as it grows) no pair of inputs that differ only in it
// scores higher at the larger, whatever the second feature.
TEST(CandidateClassifier, BoostedTreesKeepAMonotoneFeaturesDirection) {
  const Rows r = rowsBy([](float a, float b) { return a < 0.3f || (a > 0.8f && b > 0.5f); }, 600, 5);
  const auto rises = [](const BoostedTrees& trees) {
    int count = 0;
    for (float b = 0.05f; b < 1.0f; b += 0.1f)
      for (float a = 0.0f; a < 0.99f; a += 0.02f)
        count += trees.score({a + 0.02f, b}) > trees.score({a, b}) + 1e-6f;
    return count;
  };
  EXPECT_GT(rises(fitBoostedTrees(r.x, r.y, r.w)), 0);
  BoostingOptions monotone;
  monotone.monotone = {-1, 0};
  const BoostedTrees trees = fitBoostedTrees(r.x, r.y, r.w, monotone);
  EXPECT_EQ(rises(trees), 0);
  EXPECT_GT(trees.score({0.1f, 0.5f}), trees.score({0.5f, 0.5f}));  // it still learns the low end
}

// Stochastic boosting: each tree grown on half of the rows still learns the checkerboard; the
// draws come from the seed alone (the same seed, the same trees; another, other trees); a tree
// allowed the least share of the features splits on one feature only.
TEST(CandidateClassifier, StochasticBoostingDrawsRowsAndFeaturesPerTreeFromItsSeed) {
  auto rule = [](float a, float b) { return (a < 0.5f) != (b < 0.5f); };
  const Rows train = rowsBy(rule, 800, 3), test = rowsBy(rule, 400, 4);
  BoostingOptions half;
  half.rowShare = 0.5f;
  const BoostedTrees trees = fitBoostedTrees(train.x, train.y, train.w, half);
  EXPECT_GT(accuracy(test, [&](const auto& x) { return 1.0 / (1.0 + std::exp(-trees.score(x))); }),
            0.9);
  EXPECT_EQ(toJson(fitBoostedTrees(train.x, train.y, train.w, half)), toJson(trees));
  half.seed = 2;
  EXPECT_NE(toJson(fitBoostedTrees(train.x, train.y, train.w, half)), toJson(trees));
  EXPECT_NE(toJson(fitBoostedTrees(train.x, train.y, train.w)), toJson(trees));

  BoostingOptions oneFeature;
  oneFeature.featureShare = 0.01f;
  int splitOnBoth = 0, splitOnOne = 0;
  for (const auto& tree : fitBoostedTrees(train.x, train.y, train.w, oneFeature).trees) {
    std::set<int> features;
    for (const auto& node : tree)
      if (node.feature >= 0) features.insert(node.feature);
    splitOnBoth += features.size() > 1;
    splitOnOne += features.size() == 1;
  }
  EXPECT_EQ(splitOnBoth, 0);
  EXPECT_GT(splitOnOne, 0);

  BoostingOptions none;
  none.rowShare = 0.0f;
  EXPECT_THROW(fitBoostedTrees(train.x, train.y, train.w, none), InvalidArgument);
}

TEST(CandidateClassifier, BadTreesAndBadRowsAreRefusedWithTheirReason) {
  nlohmann::json j = {{"base", 0}, {"features", 2}, {"trees", {{{0, 0.5, 0, 2, 0}, {-1, 0, -1, -1, 1}, {-1, 0, -1, -1, 2}}}}};
  EXPECT_THROW(boostedTreesFromJson(j), InvalidArgument);  // a node pointing at itself: a loop
  j["trees"][0][0] = {5, 0.5, 1, 2, 0};
  EXPECT_THROW(boostedTreesFromJson(j), InvalidArgument);  // feature 5 of 2
  j["trees"][0][0] = {0, 0.5, 1, 2, 0};
  EXPECT_NO_THROW(boostedTreesFromJson(j));
  EXPECT_THROW(fitCandidateClassifier({{0.0f}, {1.0f}}, {true, true}, {1, 1}), InvalidArgument);
  EXPECT_THROW(fitBoostedTrees({}, {}, {}), InvalidArgument);
  EXPECT_THROW(fitCandidateClassifier({{0.0f}, {1.0f, 2.0f}}, {true, false}, {1, 1}),
               InvalidArgument);
}

PointCandidate candidateAt(float x, bool kept) {
  return {Eigen::Vector3f(x, 0, 0), 0.0f, kept, {x}};
}

TEST(CandidateClassifier, TheChoiceKeepsAndAddsByItsTwoThresholdsAndSuppressesNeighbours) {
  const std::vector<PointCandidate> c = {candidateAt(0.0f, true), candidateAt(0.02f, true),
                                         candidateAt(0.3f, false), candidateAt(0.31f, false),
                                         candidateAt(0.6f, false)};
  const std::vector<float> p = {0.35f, 0.3f, 0.9f, 0.8f, 0.45f};
  // Kept points stay from 0.3 up and stand beside each other; others join from 0.5, the one
  // beside a better one is suppressed; 0.45 is too little to join.
  EXPECT_EQ(chooseCandidates(p, c, {0.3f, 0.5f, 0.05f}), (std::vector<std::size_t>{2, 0, 1}));
  // The passes' points as they are: keep every kept point, add nothing.
  EXPECT_EQ(chooseCandidates(p, c, {0.0f, 1.01f, 0.05f}), (std::vector<std::size_t>{0, 1}));
  // Nothing reaches its threshold: the best alone.
  EXPECT_EQ(chooseCandidates(p, c, {0.99f, 0.99f, 0.05f}), (std::vector<std::size_t>{2}));
  EXPECT_TRUE(chooseCandidates({}, {}, {}).empty());
}

TEST(CandidateClassifier, ATakenCandidateBringsItsCopiesAtOrAboveTheCopyThreshold) {
  // A knob row: 0 is sure, 1 and 2 are its copies' places with little probability of their own,
  // 3 is a copy too close to 0; 4 is a lone candidate as unsure as the copies.
  std::vector<PointCandidate> c = {candidateAt(0.0f, false), candidateAt(0.2f, false),
                                   candidateAt(0.4f, false), candidateAt(0.01f, false),
                                   candidateAt(0.6f, false)};
  c[0].copies = {1, 2, 3};
  c[1].copies = {0, 2, 3};
  c[2].copies = {0, 1, 3};
  c[3].copies = {0, 1, 2};
  const std::vector<float> p = {0.9f, 0.15f, 0.08f, 0.5f, 0.15f};
  PointChoice choice{0.5f, 0.5f, 0.05f};
  // Copies off (the default): the sure one alone (3 is suppressed beside it).
  EXPECT_EQ(chooseCandidates(p, c, choice), (std::vector<std::size_t>{0}));
  // From 0.1: the copy at 0.15 comes with it, not the one at 0.08 nor the lone candidate.
  choice.copyThreshold = 0.1f;
  EXPECT_EQ(chooseCandidates(p, c, choice), (std::vector<std::size_t>{0, 1}));
  // From 0: every copy's place not beside a taken point.
  choice.copyThreshold = 0.0f;
  EXPECT_EQ(chooseCandidates(p, c, choice), (std::vector<std::size_t>{0, 1, 2}));
  // The best alone when nothing reaches its threshold still brings its copies.
  choice.addThreshold = 0.95f;
  EXPECT_EQ(chooseCandidates(p, c, choice), (std::vector<std::size_t>{0, 1, 2}));
}

// Three candidates: the object's most probable, a copy of its part at its height that the first
// look missed, and a likelier candidate of another shape lower down.
TEST(CandidateContext, ACopyOfTheBestCandidatesPartLooksLikeItsCompany) {
  const auto& names = candidateFeatureNames();
  const auto at = [&](const char* name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  std::vector<PointCandidate> c(3);
  for (auto& candidate : c) candidate.features.assign(names.size(), 0.0f);
  for (std::size_t i : {0u, 1u}) {
    c[i].features[at("on_part")] = 1;
    c[i].features[at("part_size")] = 0.05f;
    c[i].features[at("part_roundness")] = 0.9f;
    c[i].features[at("height")] = 0.8f;
  }
  c[2].features[at("height")] = 0.3f;
  const std::vector<float> p = {0.9f, 0.2f, 0.4f};
  const auto x = contextFeatures(c, p);
  ASSERT_EQ(x.size(), 3u);
  ASSERT_EQ(x[0].size(), kContextFeatureCount);
  ASSERT_EQ(contextFeatureNames().size(), kContextFeatureCount);
  EXPECT_FLOAT_EQ(x[0][0], 0.9f);  // first look
  EXPECT_FLOAT_EQ(x[0][1], 1.0f);  // against the best: itself
  EXPECT_FLOAT_EQ(x[0][2], 0.0f);  // rank
  EXPECT_FLOAT_EQ(x[1][2], 1.0f);
  EXPECT_FLOAT_EQ(x[2][2], 0.5f);
  EXPECT_FLOAT_EQ(x[1][3], 0.0f);  // at the best one's height and shape
  EXPECT_FLOAT_EQ(x[1][4], 0.0f);
  EXPECT_GT(x[2][3], 0.4f);
  EXPECT_GT(x[2][4], 1.0f);
  EXPECT_FLOAT_EQ(x[1][5], 0.9f);  // looks exactly like the best
  EXPECT_LT(x[2][5], 0.05f);
  const auto rows = withContext(c, p);
  ASSERT_EQ(rows[1].size(), names.size() + kContextFeatureCount);
  EXPECT_FLOAT_EQ(rows[1][at("height")], 0.8f);
  EXPECT_FLOAT_EQ(rows[1][names.size() + 5], 0.9f);
  EXPECT_TRUE(contextFeatures({}, {}).empty());
}

}  // namespace
}  // namespace sagrid
