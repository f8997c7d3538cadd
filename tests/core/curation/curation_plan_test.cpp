#include "core/curation/curation_plan.h"

#include <gtest/gtest.h>

namespace sagrid {
namespace {

AffordancePoint point(const char* type, float x, float y, AffordanceStatus status = AffordanceStatus::Predicted) {
  AffordancePoint p;
  p.type = type;
  p.position = {x, y, 0};
  p.status = status;
  return p;
}

ObjectLabels labels(const char* category, std::vector<AffordancePoint> points, double metersPerUnit = 1.0) {
  ObjectLabels l;
  l.object.category = category;
  l.object.extra["meters_per_unit"] = metersPerUnit;
  l.affordances = std::move(points);
  return l;
}

TEST(CurationPlan, RightPointsAreLeftToTheAcceptFarOnesDraggedExtraDeletedMissingAdded) {
  const ObjectLabels predicted = labels("stove", {point("heatsource", 0, 0), point("heatsource", 1, 0),
                                                  point("togglebutton", 5, 5), point("heatsource", 3, 3)});
  const ObjectLabels truth = labels("stove", {point("heatsource", 0.02f, 0), point("heatsource", 1.3f, 0),
                                              point("togglebutton", 5, 5.01f), point("togglebutton", 6, 5)});
  const std::vector<CurationStep> steps = curationPlan(predicted, truth);
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[0].action, CurationAction::Drag);  // (1,0) -> (1.3,0): 30 cm off
  EXPECT_EQ(steps[0].index, 1);
  EXPECT_FLOAT_EQ(steps[0].point.position.x(), 1.3f);
  EXPECT_EQ(steps[1].action, CurationAction::Delete);  // (3,3): a third burner where there are two
  EXPECT_EQ(steps[1].index, 3);
  EXPECT_EQ(steps[2].action, CurationAction::Add);     // the second knob
  EXPECT_FLOAT_EQ(steps[2].point.position.x(), 6.0f);
}

TEST(CurationPlan, AWrongCategoryDropsThePredictedPointsAndWrongUnitsAreSetFirst) {
  const ObjectLabels predicted = labels("none", {point("heatsource", 0, 0)});
  const ObjectLabels truth = labels("sink", {point("fluidsource", 10, 0)}, 0.01);
  const std::vector<CurationStep> steps = curationPlan(predicted, truth);
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[0].action, CurationAction::CategoryKey);  // Shift+2
  EXPECT_EQ(steps[0].category, "sink");
  EXPECT_EQ(steps[1].action, CurationAction::Units);
  EXPECT_DOUBLE_EQ(steps[1].metersPerUnit, 0.01);
  EXPECT_EQ(steps[2].action, CurationAction::Add);
  // Distances are judged in the right units: 4 units at 1 cm each is within 5 cm.
  EXPECT_TRUE(curationPlan(labels("sink", {point("fluidsource", 14, 0)}, 0.01), truth).empty());
}

// A type's last points all extra (a count that took too many, its points most probable first) go
// with one key from the first of them; an extra point before a right one goes alone.
TEST(CurationPlan, ATypesExtraTailIsDeletedWithOneKey) {
  const ObjectLabels predicted =
      labels("stove", {point("togglebutton", 0, 0), point("togglebutton", 9, 9), point("togglebutton", 1, 0),
                       point("heatsource", 0, 5), point("togglebutton", 7, 7), point("togglebutton", 8, 8)});
  const ObjectLabels truth = labels("stove", {point("togglebutton", 0, 0), point("togglebutton", 1, 0),
                                              point("heatsource", 0, 5)});
  const std::vector<CurationStep> steps = curationPlan(predicted, truth);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].action, CurationAction::DeleteRest);  // (7,7) and (8,8): the knobs' tail
  EXPECT_EQ(steps[0].index, 4);
  EXPECT_EQ(steps[1].action, CurationAction::Delete);  // (9,9), between two right knobs
  EXPECT_EQ(steps[1].index, 1);
  // One extra at the end is one Delete.
  ObjectLabels one = predicted;
  one.affordances.pop_back();
  const std::vector<CurationStep> single = curationPlan(one, truth);
  ASSERT_EQ(single.size(), 2u);
  EXPECT_EQ(single[0].action, CurationAction::Delete);
  EXPECT_EQ(single[0].index, 4);
  EXPECT_EQ(single[1].action, CurationAction::Delete);
  EXPECT_EQ(single[1].index, 1);
}

}  // namespace
}  // namespace sagrid
