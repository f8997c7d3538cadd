// annotate's control records: every toggle button point of the analytic stove gets its knob part
// and the burner it drives; a curated record is kept.
#include "core/controls/control_annotation.h"

#include <gtest/gtest.h>

#include <set>

#include "core/controls/control_record.h"
#include "support/labelled_objects.h"

namespace sagrid {
namespace {

ObjectLabels analyticStoveLabels() {
  ObjectLabels labels;
  labels.object.category = "stove";
  for (float x : {-0.15f, 0.15f})
    for (float y : {-0.1f, 0.1f}) labels.affordances.push_back(test::affordance("heatsource", {x, y, 0.1f}));
  for (float x : {-0.2f, -0.07f, 0.07f, 0.2f})
    labels.affordances.push_back(test::affordance("togglebutton", {x, -0.27f, 0.05f}));
  return labels;
}

TEST(ControlAnnotation, EveryKnobRecordsItsPartAndItsBurner) {
  ObjectLabels labels = analyticStoveLabels();
  EXPECT_TRUE(annotateControls(labels, test::analyticStoveMesh()).empty());
  std::set<int> driven;
  for (const auto& p : labels.affordances) {
    const auto record = readControlRecord(p, UpAxis::Z, "labels.json");
    EXPECT_EQ(record.has_value(), p.type == "togglebutton");
    if (!record) continue;
    EXPECT_EQ(record->part.triangles.size(), 12u);
    EXPECT_EQ(record->part.motion, ControlMotion::Knob);
    ASSERT_TRUE(record->drives);
    driven.insert(*record->drives);
  }
  EXPECT_EQ(driven, (std::set<int>{0, 1, 2, 3}));
}

TEST(ControlAnnotation, ACuratedRecordIsKept) {
  ObjectLabels labels = analyticStoveLabels();
  AffordancePoint& knob = labels.affordances[4];
  knob.status = AffordanceStatus::Edited;
  ControlRecord curated;
  curated.part.motion = ControlMotion::Button;
  curated.part.origin = PartOrigin::Disc;
  curated.drives = 3;
  writeControlRecord(knob, curated, UpAxis::Z);
  annotateControls(labels, test::analyticStoveMesh());
  const auto record = readControlRecord(labels.affordances[4], UpAxis::Z, "labels.json");
  ASSERT_TRUE(record);
  EXPECT_EQ(record->part.motion, ControlMotion::Button);
  EXPECT_EQ(record->drives, 3);
}

}  // namespace
}  // namespace sagrid
