#include "core/eval/size_memory_loso.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sagrid {
namespace {

// Fridges (1.8 m, tall shape) and microwaves (0.5 m, squat shape) from four sources; the sources
// "game-a" and "game-b" are in units of 0.25 m, which metres also fit.
std::vector<UnitsCase> appliances() {
  std::vector<UnitsCase> cases;
  auto add = [&](const std::string& source, bool fridge, double metersPerUnit, float jitter) {
    UnitsCase c;
    const double meters = fridge ? 1.8 : 0.5;
    c.object.id = source + (fridge ? "/fridge" : "/microwave");
    c.object.source = source;
    c.object.category = "none";
    c.object.descriptor =
        fridge ? std::vector<float>{1.0f + jitter, 0.3f} : std::vector<float>{0.4f, 0.9f + jitter};
    c.object.extentUnits = meters / metersPerUnit;
    c.object.metersPerUnit = metersPerUnit;
    c.group = metersPerUnit == 1.0 ? "metres" : "game";
    cases.push_back(c);
  };
  int i = 0;
  for (const char* source : {"real-a", "real-b", "real-c", "real-d"}) {
    add(source, true, 1.0, 0.01f * float(i));
    add(source, false, 1.0, 0.01f * float(i++));
  }
  add("game-a", true, 0.25, 0.02f);
  add("game-a", false, 0.25, 0.02f);
  add("game-b", true, 0.2, 0.03f);
  return cases;
}

TEST(SizeMemoryLoso, TheMemoryScalesGameFilesTheNamedUnitsGetWrong) {
  const double never = std::numeric_limits<double>::infinity();
  const auto report = evaluateSizeMemory(appliances(), {2.0, never}, "hash");
  ASSERT_EQ(report.groups, (std::vector<std::string>{"game", "metres"}));
  const UnitsScore& memoryAll = report.byFactor[0].back();
  const UnitsScore& namedAll = report.byFactor[1].back();
  EXPECT_EQ(memoryAll.objects, 11u);
  // Named units: a game fridge of 7.2 or 9 units is in no named unit's reach of 1.8 m except
  // millimetres and centimetres that make it tiny; a game microwave of 2 units is "2 m".
  EXPECT_EQ(namedAll.notMetres, 3u);
  EXPECT_EQ(namedAll.notMetresRight, 0u);
  EXPECT_EQ(memoryAll.notMetresRight, 3u);
  EXPECT_EQ(memoryAll.right, 11u);
  // The factor is chosen per source on the others, and the memory wins on all of them.
  EXPECT_EQ(report.chosenBySource.size(), 6u);
  for (const auto& [source, factor] : report.chosenBySource) EXPECT_DOUBLE_EQ(factor, 2.0) << source;
  EXPECT_EQ(report.chosenLeavingSourceOut.back().right, 11u);
  EXPECT_DOUBLE_EQ(report.chosenOnAll, 2.0);
  const std::string md = unitsLosoMarkdown(report);
  EXPECT_NE(md.find("| named units only (no memory) |"), std::string::npos) << md;
  EXPECT_NE(md.find("2 (6 sources)"), std::string::npos) << md;
}

TEST(SizeMemoryLoso, AnObjectIsNeverRecalledFromItsOwnSource) {
  // One source alone: with it left out the memory holds nothing, so the named units decide.
  std::vector<UnitsCase> cases = appliances();
  cases.resize(2);  // real-a's fridge and microwave
  cases[0].object.metersPerUnit = 0.25;
  cases[0].object.extentUnits = 1.8 / 0.25;
  const auto report = evaluateSizeMemory(cases, {1.5}, "hash");
  EXPECT_EQ(report.byFactor[0].back().notMetresRight, 0u);
  ASSERT_EQ(report.wrongChosen.size(), 1u);
  EXPECT_NE(report.wrongChosen[0].find("real-a/fridge (real-a, none)"), std::string::npos) << report.wrongChosen[0];
}

TEST(SizeMemoryLoso, AMemoryGrowsWithNewlyCuratedObjects) {
  const std::vector<UnitsCase> cases = appliances();
  std::vector<RememberedSize> entries;
  for (const auto& c : cases) entries.push_back(c.object);
  const SizeMemory memory(entries, "hash", 4.0);
  const auto again = casesOfMemory(memory);
  ASSERT_EQ(again.size(), cases.size());
  EXPECT_EQ(again[8].group, "memory");
  EXPECT_DOUBLE_EQ(again[8].object.extentUnits, cases[8].object.extentUnits);
  // A game fridge curated again (other units) replaces its entry; a new object joins.
  UnitsCase recurated = cases[8];
  recurated.object.metersPerUnit = 0.3;
  UnitsCase added = cases[0];
  added.object.id = "real-e/fridge";
  added.object.source = "real-e";
  const auto merged = mergeCases(again, {recurated, added});
  ASSERT_EQ(merged.size(), cases.size() + 1);
  EXPECT_EQ(std::count_if(merged.begin(), merged.end(),
                          [](const UnitsCase& c) { return c.object.id == "game-a/fridge"; }),
            1);
  EXPECT_DOUBLE_EQ(merged[merged.size() - 2].object.metersPerUnit, 0.3);
}

}  // namespace
}  // namespace sagrid
