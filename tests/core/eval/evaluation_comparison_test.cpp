#include "core/eval/evaluation_comparison.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid {
namespace {

EvaluationReport reportWithError(double heatError, std::size_t objects) {
  EvaluationReport r;
  r.dataDir = "/data/real-val";
  r.objects = objects;
  r.modelNames = {"stove.heatsource"};
  MethodMetrics paper;
  paper.method = "SAGrid argmin (paper)";
  paper.byModel["stove.heatsource"].paperError = heatError;
  r.methods.push_back(paper);
  CuratorEffortAccumulator effort;
  PointEdits e;
  e.drags = 1;
  e.handPoints = 4;
  effort.addObject(e);
  r.effort = effort.result();
  return r;
}

TEST(EvaluationComparison, PutsEachModelSetOnItsOwnRow) {
  const auto shipped = reportWithError(0.091, 3);
  const auto tuned = reportWithError(0.042, 3);
  const std::string md = comparisonMarkdown({{"shipped", &shipped}, {"tuned", &tuned}});
  EXPECT_NE(md.find("| shipped | 0.0910 | 0.0910 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| tuned | 0.0420 | 0.0420 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| tuned | 1.00 | 4.00 | 0.25 | 0.0 % |"), std::string::npos) << md;
  const auto j = comparisonJson({{"shipped", &shipped}, {"tuned", &tuned}});
  ASSERT_EQ(j.size(), 2u);
  EXPECT_DOUBLE_EQ(j[1]["paper_error_avg_m"].get<double>(), 0.042);
}

TEST(EvaluationComparison, RefusesReportsOnDifferentData) {
  const auto a = reportWithError(0.05, 3);
  const auto b = reportWithError(0.05, 4);
  EXPECT_THROW(comparisonMarkdown({{"a", &a}, {"b", &b}}), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
