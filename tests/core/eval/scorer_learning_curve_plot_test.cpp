#include "core/eval/scorer_learning_curve_plot.h"

#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

PointChoiceFigures figures(std::size_t edits, std::size_t handPoints, double error) {
  PointChoiceFigures f;
  f.edits.drags = edits;
  f.edits.handPoints = handPoints;
  f.singleError = error;
  f.singleErrors = 1;
  return f;
}

// Two sources of 3 and 5 objects; generated only: 10 edits of 20 hand points, 8 cm.
ScorerCrossValidation twoSources() {
  ScorerCrossValidation cv;
  cv.folds.resize(2);
  cv.folds[0].objects = 3, cv.folds[1].objects = 5;
  cv.realObjects = 8;
  cv.generatedOnly = figures(10, 20, 0.08);
  cv.ks = {0, 2};
  cv.curve = {figures(10, 20, 0.08), figures(9, 20, 0.06)};
  cv.withCurated = figures(7, 20, 0.04);
  return cv;
}

TEST(ScorerLearningCurve, EachKReadsAsAShareOfGeneratedOnly) {
  const auto series = scorerCurveSeries(twoSources());
  ASSERT_EQ(series.size(), 2u);  // no tuned-on sources: no second pair
  // The last point is all the other sources' objects: 5 and 3 over the two folds, 4 on average.
  EXPECT_EQ(series[0].k, (std::vector<double>{0, 2, 4}));
  ASSERT_EQ(series[0].share.size(), 3u);
  EXPECT_DOUBLE_EQ(series[0].share[0], 1.0);
  EXPECT_DOUBLE_EQ(series[0].share[1], 0.9);
  EXPECT_DOUBLE_EQ(series[0].share[2], 0.7);
  EXPECT_NEAR(series[1].share[1], 0.75, 1e-12);
  EXPECT_NEAR(series[1].share[2], 0.5, 1e-12);
}

TEST(ScorerLearningCurve, AFigureWithoutGroundTruthIsLeftOutAndTunedOnSourcesGetTheirOwn) {
  auto cv = twoSources();
  cv.curve[1].singleErrors = 0;  // no error measured at k = 2
  cv.tunedOn = {"made-on"};
  cv.unseenGeneratedOnly = figures(4, 8, 0.1);
  cv.unseenCurve = {figures(4, 8, 0.1), figures(2, 8, 0.1)};
  cv.unseenWithCurated = figures(2, 8, 0.05);
  const auto series = scorerCurveSeries(cv);
  ASSERT_EQ(series.size(), 4u);
  EXPECT_EQ(series[1].k, (std::vector<double>{0, 4}));
  EXPECT_EQ(series[2].share, (std::vector<double>{1.0, 0.5, 0.5}));
  EXPECT_EQ(series[3].share, (std::vector<double>{1.0, 1.0, 0.5}));
}

TEST(ScorerLearningCurve, APngIsWrittenOnlyWithACurve) {
  const auto dir = test::freshTempDir();
  writeScorerLearningCurvePng(twoSources(), dir / "curve.png");
  const std::string png = readFileBytes(dir / "curve.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  auto none = twoSources();
  none.ks.clear();
  writeScorerLearningCurvePng(none, dir / "none.png");
  EXPECT_FALSE(std::filesystem::exists(dir / "none.png"));
}

}  // namespace
}  // namespace sagrid
