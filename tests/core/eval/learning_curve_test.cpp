#include <gtest/gtest.h>

#include <algorithm>

#include "core/common/error.h"
#include "core/eval/learning_curve.h"

namespace sagrid {
namespace {

TEST(LearningCurve, FoldsAreDisjointCoverEveryObjectOnceAndAreReproducible) {
  const auto folds = kFoldSplit(11, 3, 5);
  ASSERT_EQ(folds.size(), 3u);
  std::vector<int> seen(11, 0);
  for (const auto& f : folds) {
    EXPECT_GE(f.size(), 3u);  // sizes differ by at most one: 4, 4, 3
    EXPECT_LE(f.size(), 4u);
    for (std::size_t i : f) ++seen[i];
  }
  for (int s : seen) EXPECT_EQ(s, 1);
  EXPECT_EQ(kFoldSplit(11, 3, 5), folds);
  EXPECT_NE(kFoldSplit(11, 3, 6), folds);  // the seed matters
  EXPECT_EQ(kFoldSplit(2, 5, 1).size(), 2u);  // clamped to the object count
  EXPECT_THROW(kFoldSplit(1, 3, 1), InvalidArgument);
  EXPECT_THROW(kFoldSplit(5, 1, 1), InvalidArgument);
}

TEST(LearningCurve, ParsesObjectCounts) {
  EXPECT_EQ(parseLearningCurveKs("0,2,5,10,all"), (std::vector<int>{0, 2, 5, 10, kAllObjects}));
  EXPECT_THROW(parseLearningCurveKs("0,x"), InvalidArgument);
  EXPECT_THROW(parseLearningCurveKs("-1"), InvalidArgument);
  EXPECT_THROW(parseLearningCurveKs(""), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
