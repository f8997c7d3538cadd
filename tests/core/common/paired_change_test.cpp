// The guards' one rule: a candidate is adopted only where its per-object figures beat the current
// ones by more than the standard error of their differences. Known numbers worked by hand.
#include "core/common/paired_change.h"

#include <gtest/gtest.h>

namespace sagrid {
namespace {

TEST(PairedChange, ABetterMeanBeyondItsStandardErrorIsAdopted) {
  // Differences -1, -1, 0, 0: mean -0.5, sample sd sqrt(1/3), standard error sqrt(1/3)/2.
  const PairedChange c = pairedChange(std::vector<ObjectFigures>{{3, 2}, {2, 1}, {1, 1}, {2, 2}});
  EXPECT_EQ(c.objects, 4u);
  EXPECT_DOUBLE_EQ(c.current, 2.0);
  EXPECT_DOUBLE_EQ(c.candidate, 1.5);
  EXPECT_NEAR(c.noise, std::sqrt(1.0 / 3) / 2, 1e-12);
  EXPECT_TRUE(c.clearlyBetter());
  EXPECT_EQ(c.verdict(), "adopted");
  EXPECT_EQ(c.lower, 2u);
  EXPECT_EQ(c.higher, 0u);
  EXPECT_EQ(c.comparison(), "better beyond its noise");
}

TEST(PairedChange, AGainWithinItsNoiseOrALossIsRefused) {
  // Differences -3, +2: mean -0.5, standard error 2.5.
  const PairedChange within = pairedChange(std::vector<ObjectFigures>{{5, 2}, {1, 3}});
  EXPECT_NEAR(within.noise, 2.5, 1e-12);
  EXPECT_FALSE(within.clearlyBetter());
  EXPECT_EQ(within.verdict(), "refused (better by less than its noise)");
  EXPECT_EQ(within.comparison(), "within its noise");
  EXPECT_EQ(within.lower, 1u);
  EXPECT_EQ(within.higher, 1u);
  const PairedChange worse = pairedChange(std::vector<ObjectFigures>{{1, 2}, {1, 2}, {1, 2}});
  EXPECT_DOUBLE_EQ(worse.noise, 0.0);
  EXPECT_FALSE(worse.clearlyBetter());
  EXPECT_EQ(worse.verdict(), "refused");
  EXPECT_EQ(worse.comparison(), "worse beyond its noise");
  EXPECT_EQ(worse.higher, 3u);
  // Equal everywhere: nothing to adopt, though the noise is zero.
  EXPECT_FALSE(pairedChange(std::vector<ObjectFigures>{{1, 1}, {2, 2}}).clearlyBetter());
}

TEST(PairedChange, OneFixAmongManyIsAsLikelyNoiseAndTwoAreNot) {
  // 0/1 figures (a category wrong): one object of n fixed changes the mean by exactly its
  // standard error, 1/n; two fixed and none broken is beyond it.
  for (int n : {5, 12, 97}) {
    std::vector<ObjectFigures> one(n, ObjectFigures{0, 0}), two(n, ObjectFigures{0, 0});
    one[0] = {1, 0};
    two[0] = two[1] = {1, 0};
    EXPECT_NEAR(pairedChange(one).noise, 1.0 / n, 1e-12) << n;
    EXPECT_FALSE(pairedChange(one).clearlyBetter()) << n;
    EXPECT_TRUE(pairedChange(two).clearlyBetter()) << n;
  }
}

TEST(PairedChange, GroupsCountEquallyAndOneObjectCannotJudge) {
  // Group A: differences -1, -1 (mean -1, sd 0); group B: 0, 0, 0, +1 (mean 0.25, variance 0.25).
  const PairedChange c = pairedChange(std::vector<std::vector<ObjectFigures>>{
      {{1, 0}, {1, 0}}, {{0, 0}, {0, 0}, {0, 0}, {0, 1}}, {}});
  EXPECT_EQ(c.objects, 6u);
  EXPECT_DOUBLE_EQ(c.current, 0.5);      // (1 + 0) / 2
  EXPECT_DOUBLE_EQ(c.candidate, 0.125);  // (0 + 0.25) / 2
  EXPECT_NEAR(c.noise, std::sqrt(0.25 / 4) / 2, 1e-12);
  EXPECT_TRUE(c.clearlyBetter());
  // A group of one object: the noise is unknown and the current model stays.
  const PairedChange lone =
      pairedChange(std::vector<std::vector<ObjectFigures>>{{{1, 0}, {1, 0}}, {{1, 0}}});
  EXPECT_TRUE(std::isnan(lone.noise));
  EXPECT_FALSE(lone.clearlyBetter());
  EXPECT_TRUE(std::isnan(pairedChange(std::vector<ObjectFigures>{}).current));
}

TEST(PairedChange, PairsTheObjectsBothJudged) {
  const auto pairs = pairById({{"a", 1}, {"b", 2}, {"c", 3}}, {{"b", 5}, {"c", 6}, {"d", 7}});
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_DOUBLE_EQ(pairs[0].current, 2);
  EXPECT_DOUBLE_EQ(pairs[0].candidate, 5);
  EXPECT_DOUBLE_EQ(pairs[1].current, 3);
  EXPECT_DOUBLE_EQ(pairs[1].candidate, 6);
}

}  // namespace
}  // namespace sagrid
