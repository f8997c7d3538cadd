// The curator's control edits (issue 42): a selected knob shows the part the exports would move
// (found on the mesh until kept), keeping it or flipping its axis or its burner writes the point's
// control record to labels.json, and undo puts the record back as it was.
#include "ui/document/control_commands.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/controls/control_record.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"
#include "ui/document/annotation_document.h"
#include "ui/document/control_view.h"

namespace sagrid::ui {
namespace {

TEST(ControlCommands, AFoundKnobIsKeptFlippedAndUndone) {
  const auto dir = test::freshTempDir();
  ObjectLabels labels;
  labels.object.category = "stove";
  labels.affordances.push_back(test::affordance("heatsource", {-0.15f, -0.1f, 0.1f}));
  labels.affordances.push_back(test::affordance("togglebutton", {-0.2f, -0.27f, 0.05f}));
  AnnotationDocument doc(std::make_shared<Mesh>(test::analyticStoveMesh()), labels,
                         dir / "labels.json");
  const auto found = shownControl(doc, 1);
  ASSERT_TRUE(found);
  EXPECT_FALSE(found->recorded);
  EXPECT_EQ(found->part.triangles.size(), 12u);
  // Found now, it shows the burner the layout pairs it with (the only one), as the exports would.
  EXPECT_EQ(found->drives, std::optional<int>(0));
  EXPECT_FALSE(shownControl(doc, 0));  // a heat source has no control

  ControlRecord kept{found->part, 0};
  doc.execute(std::make_unique<SetControlCommand>(1, controlJson(kept, UpAxis::Z), "part kept"));
  const auto recorded = shownControl(doc, 1);
  ASSERT_TRUE(recorded);
  EXPECT_TRUE(recorded->recorded);
  EXPECT_EQ(recorded->drives, 0);
  ASSERT_TRUE(readControlRecord(readLabels(dir / "labels.json").affordances[1], UpAxis::Z, "x"));

  ControlRecord flipped = kept;
  flipped.part.axis = -kept.part.axis;
  doc.execute(std::make_unique<SetControlCommand>(1, controlJson(flipped, UpAxis::Z), "axis flipped"));
  EXPECT_TRUE(shownControl(doc, 1)->part.axis.isApprox(-found->part.axis, 1e-5f));
  doc.undo();
  EXPECT_TRUE(shownControl(doc, 1)->part.axis.isApprox(found->part.axis, 1e-5f));
  doc.undo();
  EXPECT_FALSE(shownControl(doc, 1)->recorded);
  EXPECT_FALSE(readLabels(dir / "labels.json").affordances[1].extra.contains(kControlField));
}

}  // namespace
}  // namespace sagrid::ui
