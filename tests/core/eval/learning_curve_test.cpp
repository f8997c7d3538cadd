#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

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

TEST(LearningCurve, SourceFoldsAreDisjointBySourceCoverEveryObjectAndAreReproducible) {
  // 16 objects from 6 sources of unequal size.
  const std::vector<std::string> sources{"a", "a", "a", "a", "a", "b", "b", "b", "c", "c",
                                         "d", "d", "e", "f", "f", "f"};
  const auto folds = sourceFoldSplit(sources, 3, 7);
  ASSERT_EQ(folds.size(), 3u);
  std::vector<int> seen(sources.size(), 0);
  std::map<std::string, std::set<std::size_t>> foldsOfSource;
  for (std::size_t f = 0; f < folds.size(); ++f) {
    EXPECT_GE(folds[f].size(), 5u);  // 16 objects dealt largest source first: 5, 5, 6
    for (std::size_t i : folds[f]) ++seen[i], foldsOfSource[sources[i]].insert(f);
  }
  for (int s : seen) EXPECT_EQ(s, 1);
  for (const auto& [source, in] : foldsOfSource) EXPECT_EQ(in.size(), 1u) << source;
  EXPECT_EQ(sourceFoldSplit(sources, 3, 7), folds);
  EXPECT_EQ(sourceFoldSplit(sources, 50, 7).size(), 6u);  // at most one fold per source
  EXPECT_THROW(sourceFoldSplit({"a", "a", "a"}, 3, 1), InvalidArgument);
  EXPECT_THROW(sourceFoldSplit(sources, 1, 1), InvalidArgument);
}

TEST(LearningCurve, FoldsAreStratifiedByGroup) {
  // 8 stoves and 15 sinks (the Sweet Home 3D corpus) in 3 folds: 2-3 stoves and 5 sinks each.
  std::vector<std::string> groups(23, "sink");
  for (int i : {0, 4, 5, 9, 13, 17, 20, 22}) groups[i] = "stove";
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto folds = kFoldSplit(23, 3, seed, groups);
    std::vector<int> seen(23, 0);
    for (const auto& f : folds) {
      const auto stoves =
          std::count_if(f.begin(), f.end(), [&](std::size_t i) { return groups[i] == "stove"; });
      EXPECT_GE(stoves, 2);
      EXPECT_LE(stoves, 3);
      EXPECT_GE(f.size(), 7u);
      EXPECT_LE(f.size(), 8u);
      for (std::size_t i : f) ++seen[i];
    }
    for (int s : seen) EXPECT_EQ(s, 1);
    EXPECT_EQ(kFoldSplit(23, 3, seed, groups), folds);
  }
  EXPECT_THROW(kFoldSplit(5, 2, 1, {"a", "b"}), InvalidArgument);
}

// Two models, two folds: the average row is over the models, its ratio to k = 0 is the ratio of
// the averages, and a model without a value at k stays out of both.
TEST(LearningCurve, ReportAveragesTheModelsAndGivesTheRatioToKZero) {
  LearningCurveReport r;
  r.dataDir = "real", r.initDir = "models";
  r.ks = {0, kAllObjects};
  r.modelNames = {"sink.fluidsource", "stove.heatsource"};
  r.folds = {{"a"}, {"b"}};
  auto add = [&](const std::string& model, int fold, int k, double error) {
    LearningCurvePoint p;
    p.model = model, p.fold = fold, p.k = k, p.kUsed = k == 0 ? 0 : 3, p.testObjects = 1;
    p.paperError = error;
    r.points.push_back(p);
  };
  add("sink.fluidsource", 1, 0, 0.10), add("sink.fluidsource", 2, 0, 0.30);  // mean 0.20
  add("stove.heatsource", 1, 0, 0.10), add("stove.heatsource", 2, 0, 0.10);  // mean 0.10
  add("sink.fluidsource", 1, kAllObjects, 0.05), add("sink.fluidsource", 2, kAllObjects, 0.15);
  add("stove.heatsource", 1, kAllObjects, 0.08), add("stove.heatsource", 2, kAllObjects, 0.12);
  const auto j = learningCurveJson(r);
  ASSERT_EQ(j.at("average").size(), 2u);
  EXPECT_NEAR(j["average"][0]["paper_error_m_mean"].get<double>(), 0.15, 1e-12);
  EXPECT_NEAR(j["average"][0]["ratio_to_first_k"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(j["average"][1]["paper_error_m_mean"].get<double>(), 0.10, 1e-12);
  EXPECT_NEAR(j["average"][1]["ratio_to_first_k"].get<double>(), 0.10 / 0.15, 1e-12);
  EXPECT_EQ(j["average"][1]["models"], 2);
  const std::string md = learningCurveMarkdown(r);
  EXPECT_NE(md.find("| all | 2 | 10.0 | 0.67 |"), std::string::npos) << md;

  LearningCurvePoint missing;  // a third model measured only at k = 0
  missing.model = "stove.togglebutton", missing.fold = 1, missing.k = 0, missing.testObjects = 1;
  missing.paperError = 0.9;
  r.modelNames.push_back(missing.model);
  r.points.push_back(missing);
  EXPECT_EQ(learningCurveJson(r)["average"][1]["models"], 2);
  EXPECT_NEAR(learningCurveJson(r)["average"][1]["ratio_to_first_k"].get<double>(), 0.10 / 0.15,
              1e-12);
}

TEST(LearningCurve, ParsesObjectCounts) {
  EXPECT_EQ(parseLearningCurveKs("0,2,5,10,all"), (std::vector<int>{0, 2, 5, 10, kAllObjects}));
  EXPECT_THROW(parseLearningCurveKs("0,x"), InvalidArgument);
  EXPECT_THROW(parseLearningCurveKs("-1"), InvalidArgument);
  EXPECT_THROW(parseLearningCurveKs(""), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
