#include "core/eval/metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/common/error.h"
#include "core/eval/curator_effort.h"
#include "core/eval/hungarian.h"

namespace sagrid {
namespace {

double totalCost(const std::vector<std::vector<double>>& c, const std::vector<int>& a) {
  double t = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] >= 0) t += c[i][a[i]];
  return t;
}

TEST(Hungarian, SolvesAKnownSquareProblem) {
  // Classic example: optimum 4 + 2 + 5 ... picks (0,1), (1,0), (2,2) with cost 1 + 2 + 2 = 5.
  const std::vector<std::vector<double>> c = {{4, 1, 3}, {2, 0, 5}, {3, 2, 2}};
  const auto a = hungarianAssignment(c);
  EXPECT_EQ(a, (std::vector<int>{1, 0, 2}));
  EXPECT_DOUBLE_EQ(totalCost(c, a), 5.0);
}

TEST(Hungarian, HandlesRectangularMatricesBothWays) {
  const std::vector<std::vector<double>> wide = {{10, 1, 10, 10}, {10, 10, 10, 2}};
  EXPECT_EQ(hungarianAssignment(wide), (std::vector<int>{1, 3}));
  const std::vector<std::vector<double>> tall = {{10, 10}, {1, 10}, {10, 10}, {10, 2}};
  EXPECT_EQ(hungarianAssignment(tall), (std::vector<int>{-1, 0, -1, 1}));
  EXPECT_TRUE(hungarianAssignment({}).empty());
  EXPECT_THROW(hungarianAssignment({{1, 2}, {3}}), InvalidArgument);
  EXPECT_THROW(hungarianAssignment({{1, NAN}}), InvalidArgument);
}

TEST(Hungarian, MatchesBruteForceOnRandomMatrices) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> value(0, 10);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 1 + trial % 6;
    std::vector<std::vector<double>> c(n, std::vector<double>(n));
    for (auto& r : c)
      for (auto& v : r) v = value(rng);
    std::vector<int> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    double best = 1e300;
    do best = std::min(best, totalCost(c, perm));
    while (std::next_permutation(perm.begin(), perm.end()));
    EXPECT_NEAR(totalCost(c, hungarianAssignment(c)), best, 1e-9) << "trial " << trial;
  }
}

TEST(Metrics, NearestDistanceIsScaledToMetres) {
  const std::vector<Eigen::Vector3f> truth = {{0, 0, 0}, {10, 0, 0}};
  EXPECT_NEAR(nearestDistance({9, 0, 0}, truth, 0.01), 0.01, 1e-9);  // 1 cm in a cm-unit mesh
  EXPECT_TRUE(std::isinf(nearestDistance({0, 0, 0}, {}, 1.0)));
}

TEST(Metrics, MatchingCountsPrecisionRecallAndRightCount) {
  // Truth: 3 burners; predictions: two close (1 cm, 3 cm), one far (20 cm), plus a fourth extra.
  const std::vector<Eigen::Vector3f> truth = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<Eigen::Vector3f> pred = {{0.01f, 0, 0}, {1, 0.03f, 0}, {0, 1.2f, 0}, {5, 5, 5}};
  const ObjectMatch m = matchPoints(pred, truth, 1.0);
  EXPECT_EQ(m.predicted, 4u);
  EXPECT_EQ(m.truth, 3u);
  ASSERT_EQ(m.matchedErrors.size(), 3u);
  EXPECT_EQ(m.truePositives, 2u);
  TypeMetricsAccumulator acc;
  acc.addMatch(m);
  acc.addMatch(matchPoints({{0, 0, 0}}, {{0, 0, 0.04f}}, 1.0));
  acc.addSingle(0.01);
  acc.addSingle(0.03);
  const TypeMetrics r = acc.result();
  EXPECT_EQ(r.objects, 2u);
  EXPECT_NEAR(r.paperError, 0.02, 1e-9);
  EXPECT_NEAR(r.matchedError, (0.01 + 0.03 + 0.2 + 0.04) / 4, 1e-6);
  EXPECT_NEAR(r.precision, 3.0 / 5.0, 1e-9);
  EXPECT_NEAR(r.recall, 3.0 / 4.0, 1e-9);
  EXPECT_NEAR(r.countRight, 0.5, 1e-9);
}

TEST(CuratorEffort, CountsDragsDeletionsAndAdditions) {
  // Two truths; three predictions: one within 5 cm, one 20 cm off, one extra far away.
  const std::vector<Eigen::Vector3f> truth = {{0, 0, 0}, {1, 0, 0}};
  const std::vector<Eigen::Vector3f> predicted = {{0.01f, 0, 0}, {1.2f, 0, 0}, {5, 5, 5}};
  const PointEdits e = pointEdits(matchPoints(predicted, truth, 1.0));
  EXPECT_EQ(e.drags, 1u);
  EXPECT_EQ(e.deletions, 1u);
  EXPECT_EQ(e.additions, 0u);
  EXPECT_EQ(e.handPoints, 2u);
  // One prediction for two truths, correct: one point to add.
  const PointEdits missing = pointEdits(matchPoints({{1, 0, 0}}, truth, 1.0));
  EXPECT_EQ(missing.total(), 1u);
  EXPECT_EQ(missing.additions, 1u);
  // Predictions where the object has none of the type: each one is deleted.
  const PointEdits extras = pointEdits(matchPoints({{1, 0, 0}, {2, 0, 0}}, {}, 1.0));
  EXPECT_EQ(extras.deletions, 2u);
  EXPECT_EQ(extras.handPoints, 0u);
}

TEST(CuratorEffort, AggregatesPerObjectAndOneKeyShare) {
  CuratorEffortAccumulator acc;
  PointEdits perfect;
  perfect.handPoints = 4;
  PointEdits twoEdits;
  twoEdits.drags = 1;
  twoEdits.additions = 1;
  twoEdits.handPoints = 2;
  acc.addObject(perfect);
  acc.addObject(twoEdits);
  const CuratorEffort r = acc.result();
  EXPECT_EQ(r.objects, 2u);
  EXPECT_DOUBLE_EQ(r.editsPerObject, 1.0);
  EXPECT_DOUBLE_EQ(r.handPointsPerObject, 3.0);
  EXPECT_DOUBLE_EQ(r.oneKeyShare, 0.5);
  EXPECT_TRUE(std::isnan(CuratorEffortAccumulator().result().editsPerObject));
}

}  // namespace
}  // namespace sagrid
