#include "core/eval/count_breakdown.h"

#include <gtest/gtest.h>

#include "core/eval/evaluation_comparison.h"

namespace sagrid {
namespace {

constexpr const char* kAuto = "SAGrid auto count";

// One evaluated stove as EvaluationReport::perObject records it: `truthKnobs` labelled knobs,
// `foundKnobs` automatic-count points, `edits` deletions, made with the given controls.
nlohmann::json stove(const std::string& controls, int truthKnobs, int foundKnobs, int edits = 0) {
  nlohmann::json o = {{"id", "stove"}, {"category", "stove"}};
  o["generator"] = {{"controls", controls},
                    {"finish", "stainless"},
                    {"knobs", truthKnobs},
                    {"realism", {{"colors", "material"}}}};
  o["truth"]["stove.togglebutton"] = nlohmann::json::array();
  for (int i = 0; i < truthKnobs; ++i) o["truth"]["stove.togglebutton"].push_back({0, 0, i});
  o["predictions"]["stove.togglebutton"][kAuto] = nlohmann::json::array();
  for (int i = 0; i < foundKnobs; ++i)
    o["predictions"]["stove.togglebutton"][kAuto].push_back({0, 0, i});
  o["edits"]["stove.togglebutton"] = {{"drags", 0}, {"deletions", edits}, {"additions", 0}};
  return o;
}

TEST(CountBreakdown, GroupsObjectsByEachStringSettingWithSeveralValues) {
  const nlohmann::json objects = {stove("touch", 5, 1, 4), stove("touch", 2, 2),
                                  stove("front_panel", 4, 6, 2), stove("front_panel", 3, 3)};
  const CountBreakdown b = countBreakdown(objects);
  ASSERT_EQ(b.groups.size(), 1u);
  const auto& settings = b.groups.at("stove.togglebutton");
  // "finish" has one value and says nothing; numbers and nested objects are no groups.
  EXPECT_EQ(settings.size(), 1u);
  const CountGroup& touch = settings.at("controls").at("touch");
  EXPECT_EQ(touch.objects, 2u);
  EXPECT_EQ(touch.right, 1u);
  EXPECT_EQ(touch.fewer, 1u);
  EXPECT_EQ(touch.more, 0u);
  EXPECT_EQ(touch.edits, 4u);
  const CountGroup& panel = settings.at("controls").at("front_panel");
  EXPECT_EQ(panel.right, 1u);
  EXPECT_EQ(panel.more, 1u);
  const std::string md = countBreakdownMarkdown(b);
  EXPECT_NE(md.find("| controls | touch | 2 | 50 % | 1 | 0 | 2.00 |"), std::string::npos) << md;
  EXPECT_EQ(countBreakdownJson(b)["stove.togglebutton"]["controls"]["front_panel"]["more"], 1);
}

TEST(CountBreakdown, LeavesOutObjectsWithoutGeneratorOrTruth) {
  nlohmann::json real = stove("touch", 3, 3);
  real.erase("generator");
  nlohmann::json noKnobs = stove("front_panel", 2, 2);
  noKnobs["truth"].erase("stove.togglebutton");
  const CountBreakdown b = countBreakdown(nlohmann::json{real, noKnobs, stove("touch", 1, 1)});
  // One object left with one value of each setting: nothing to break down.
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(countBreakdownMarkdown(b), "");
}

TEST(CountBreakdown, ComparisonPutsEachModelSetsShareSideBySide) {
  EvaluationReport before, after;
  before.dataDir = after.dataDir = "/data/stoves";
  before.objects = after.objects = 2;
  before.perObject = {stove("touch", 4, 1), stove("top_beside", 2, 2)};
  after.perObject = {stove("touch", 4, 4), stove("top_beside", 2, 3)};
  const std::string md = comparisonMarkdown({{"shipped", &before}, {"new", &after}});
  EXPECT_NE(md.find("| Model | Setting | Value | Objects | shipped | new |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| stove.togglebutton | controls | touch | 1 | 0 % | 100 % |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| stove.togglebutton | controls | top_beside | 1 | 100 % | 0 % |"),
            std::string::npos)
      << md;
}

}  // namespace
}  // namespace sagrid
