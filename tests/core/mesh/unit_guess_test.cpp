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

TEST(UnitGuess, AGameFileFarFromTheSizeOfObjectsLikeItIsScaledToThatSize) {
  // A microwave 2.73 units wide fits the appliance range in metres; curated microwaves are 0.5 m.
  const UnitGuess named = guessMetersPerUnit(2.73, "none");
  ASSERT_EQ(named.unit, "m");
  const UnitGuess scaled = unlessFarFromExpectedSize(named, 2.73, 0.5, 4.0);
  EXPECT_NEAR(scaled.metersPerUnit, 0.5 / 2.73, 1e-12);
  EXPECT_EQ(scaled.unit, "custom");
  EXPECT_FALSE(scaled.sure);
  EXPECT_NE(scaled.reason.find("curated objects like it"), std::string::npos) << scaled.reason;
  // Within the factor, or with nothing to go by, the named unit stays.
  EXPECT_EQ(unlessFarFromExpectedSize(named, 2.73, 0.8, 4.0).unit, "m");
  EXPECT_EQ(unlessFarFromExpectedSize(named, 2.73, 0.0, 4.0).unit, "m");
  EXPECT_EQ(unlessFarFromExpectedSize(named, 2.73, std::nan(""), 4.0).unit, "m");
  EXPECT_EQ(unlessFarFromExpectedSize(named, 0.0, 0.5, 4.0).unit, "m");
  // A scale that lands on a named unit is called by its name: metres assumed, 90 units expected at 0.9 m.
  EXPECT_EQ(unlessFarFromExpectedSize(UnitGuess{}, 90.0, 0.9, 4.0).unit, "cm");
}

}  // namespace
}  // namespace sagrid
