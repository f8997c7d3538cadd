#include "core/annotate/category_rules.h"

#include <gtest/gtest.h>

namespace sagrid {
namespace {

TEST(CategoryRules, StovesGetTheirOwnRules) {
  const CategoryRules stove = categoryRulesFor("stove");
  EXPECT_TRUE(stove.printedMarks);
  EXPECT_TRUE(stove.repeatedParts.separationBySpacing);
  EXPECT_GT(stove.repeatedParts.snapPartVoxels, 0.0f);
  EXPECT_GE(stove.repeatedParts.sureKnobRow, 3);
  ASSERT_TRUE(stove.burnerCaps.has_value());
  EXPECT_TRUE(stove.burnerCaps->roundFlatSeeds);
  EXPECT_GT(stove.burnerCaps->maxCopyScale, 1.0f);
  EXPECT_TRUE(stove.partOwnership.onePointPerPart);
  EXPECT_GT(stove.partOwnership.strayRowSpacings, 0.0f);
  EXPECT_GT(stove.partOwnership.footHeight, 0.0f);
  EXPECT_EQ(stove.spoutControls.reachVoxels, 0.0f);  // a stove has no spout
}

TEST(CategoryRules, SinksMoveTogglePointsOffTheSpout) {
  EXPECT_GT(categoryRulesFor("sink").spoutControls.reachVoxels, 0.0f);
}

TEST(CategoryRules, SinksAndOtherCategoriesKeepTheDefaults) {
  for (const std::string category : {"sink", "none", "microwave"}) {
    SCOPED_TRACE(category);
    const CategoryRules rules = categoryRulesFor(category);
    EXPECT_FALSE(rules.printedMarks);
    EXPECT_FALSE(rules.repeatedParts.separationBySpacing);
    EXPECT_EQ(rules.repeatedParts.snapPartVoxels, 0.0f);
    EXPECT_EQ(rules.repeatedParts.sureKnobRow, 0);
    EXPECT_FALSE(rules.burnerCaps.has_value());
    EXPECT_GT(rules.repeatedParts.pairReachVoxels, 0.0f);
    EXPECT_FALSE(rules.partOwnership.onePointPerPart);
    EXPECT_EQ(rules.partOwnership.strayRowSpacings, 0.0f);
    EXPECT_GT(rules.partOwnership.footHeight, 0.0f);
  }
}

}  // namespace
}  // namespace sagrid
