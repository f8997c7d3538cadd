#include "core/mesh/unit_guess.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sagrid {
namespace {

TEST(UnitGuess, AStoveNinetyUnitsAcrossIsInCentimetresAndOneInMetresStays) {
  const UnitGuess cm = guessMetersPerUnit(90.0, "stove");
  EXPECT_EQ(cm.unit, "cm");
  EXPECT_DOUBLE_EQ(cm.metersPerUnit, 0.01);
  EXPECT_TRUE(cm.sure);  // 90 m, 0.09 m and 2.3 m are no stove
  const UnitGuess m = guessMetersPerUnit(0.9, "stove");
  EXPECT_EQ(m.unit, "m");
  EXPECT_NE(m.reason.find("0.9 m"), std::string::npos) << m.reason;
}

TEST(UnitGuess, MillimetresAndInchesWhereOnlyTheyFit) {
  EXPECT_EQ(guessMetersPerUnit(600.0, "stove").unit, "mm");    // 6 m in cm, 0.6 m in mm
  EXPECT_EQ(guessMetersPerUnit(36.0, "stove").unit, "cm");     // 0.36 m in cm beats 0.91 m in inches: cm is likelier
  EXPECT_FALSE(guessMetersPerUnit(36.0, "stove").sure);
  EXPECT_EQ(guessMetersPerUnit(12.0, "stove").unit, "in");     // 0.12 m in cm is too small for a stove
}

TEST(UnitGuess, OutsideEveryRangeTheNearestUnitAndNoExtentKeepsMetres) {
  EXPECT_EQ(guessMetersPerUnit(5e6, "sink").unit, "mm");  // 5 km in mm is the least absurd
  EXPECT_EQ(guessMetersPerUnit(0.0, "sink").unit, "m");
  EXPECT_DOUBLE_EQ(guessMetersPerUnit(std::nan(""), "none").metersPerUnit, 1.0);
}

}  // namespace
}  // namespace sagrid
