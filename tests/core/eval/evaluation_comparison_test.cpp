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

// Per-object records as evaluation writes them: `drags[i]` edits and `errors[i]` m on object i.
EvaluationReport reportOfObjects(const std::vector<int>& drags, const std::vector<double>& errors) {
  EvaluationReport r = reportWithError(0.05, drags.size());
  for (std::size_t i = 0; i < drags.size(); ++i)
    r.perObject.push_back(
        {{"id", "o" + std::to_string(i)},
         {"edits", {{"stove.heatsource", {{"drags", drags[i]}, {"additions", 0}}}}},
         {"paper_error_m", {{"stove.heatsource", errors[i]}}}});
  return r;
}

TEST(EvaluationComparison, PairsEachSetWithTheFirstObjectByObject) {
  const auto first = reportOfObjects({1, 1, 1, 1}, {0.10, 0.10, 0.10, 0.10});
  // Edits: two objects fixed, none broken (mean 1 -> 0.5, noise 0.29): better beyond its noise.
  // Errors: one object 4 cm better, one 4 cm worse: within its noise.
  const auto second = reportOfObjects({0, 0, 1, 1}, {0.06, 0.14, 0.10, 0.10});
  // Edits: one fixed of four moves the mean by exactly its noise: within it. Errors: all 2 cm
  // worse: worse beyond its noise (no spread, noise 0).
  const auto third = reportOfObjects({0, 1, 1, 1}, {0.12, 0.12, 0.12, 0.12});
  const std::string md =
      comparisonMarkdown({{"shipped", &first}, {"two fixed", &second}, {"one fixed", &third}});
  EXPECT_NE(
      md.find("| two fixed | 1.00 -> 0.50 (noise 0.29), lower on 2, higher on 0: better beyond "
              "its noise | 10.0 -> 10.0 (noise 1.6), lower on 1, higher on 1: within its noise |"),
      std::string::npos)
      << md;
  EXPECT_NE(
      md.find("| one fixed | 1.00 -> 0.75 (noise 0.25), lower on 1, higher on 0: within its noise "
              "| 10.0 -> 12.0 (noise 0.0), lower on 0, higher on 4: worse beyond its noise |"),
      std::string::npos)
      << md;
  const auto j = comparisonJson({{"shipped", &first}, {"two fixed", &second}});
  EXPECT_FALSE(j[0].contains("against_first"));
  EXPECT_EQ(j[1]["against_first"]["edits"]["verdict"], "better beyond its noise");
  EXPECT_EQ(j[1]["against_first"]["edits"]["objects"], 4);
  EXPECT_DOUBLE_EQ(j[1]["against_first"]["edits"]["this"].get<double>(), 0.5);
}

TEST(EvaluationComparison, RefusesReportsOnDifferentData) {
  const auto a = reportWithError(0.05, 3);
  const auto b = reportWithError(0.05, 4);
  EXPECT_THROW(comparisonMarkdown({{"a", &a}, {"b", &b}}), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
