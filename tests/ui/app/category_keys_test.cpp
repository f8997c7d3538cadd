// The object's category by its own key (Shift+1 stove, Shift+2 sink, Shift+3 none): the same
// undoable switch as the Object panel's list, logged as `category_key`, which the keystroke-level
// model counts as a key instead of a trip to the list; the replayed curator's plan uses it.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <fstream>

#include "core/annotate/suggested_points.h"
#include "core/curation/curation_plan.h"
#include "core/curation/curation_report.h"
#include "support/curation_counts.h"
#include "support/test_paths.h"
#include "ui/app/session.h"
#include "ui/app/shortcuts.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// A stove with two predicted points, or (rejected) the same filed as "none" with them suggested.
fs::path writeStove(const fs::path& dir, bool rejected) {
  fs::create_directories(dir);
  std::ofstream(dir / "mesh.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
  ObjectLabels labels;
  labels.object.id = "stove";
  labels.object.mesh = "mesh.obj";
  labels.object.category = rejected ? "none" : "stove";
  labels.object.up = "z";
  AffordancePoint p;
  p.type = "heatsource";
  p.position = {0.5f, 0.5f, 0.0f};
  labels.affordances = {p, p};
  labels.affordances[1].type = "togglebutton";
  if (rejected) markSuggestions(labels, "stove");
  writeLabels(dir / "labels.json", labels);
  return dir / "labels.json";
}

void press(Session& session, int key, int mods) {
  handleShortcuts({InputEvent::keyEvent(key, true, mods)}, session, false);
}

TEST(CategoryKeys, ShiftTwoFilesAStoveAsASinkInOneUndoableStepLoggedAsTheKey) {
  const fs::path dir = test::freshTempDir();
  const fs::path labels = writeStove(dir / "stove", false);
  Session session;
  session.autoPredict = false;
  session.setCurationLog(dir / "curation.jsonl");
  session.openPaths({labels.parent_path()});
  press(session, GLFW_KEY_2, GLFW_MOD_SHIFT);
  const ObjectLabels switched = readLabels(labels);
  EXPECT_EQ(switched.object.category, "sink");
  EXPECT_TRUE(switched.affordances.empty());  // the stove's predicted points go with its category
  EXPECT_EQ(test::loggedActions(dir / "curation.jsonl", CurationAction::CategoryKey), 1);
  EXPECT_EQ(test::loggedActions(dir / "curation.jsonl", CurationAction::Category), 0);
  session.undo();
  const ObjectLabels back = readLabels(labels);
  EXPECT_EQ(back.object.category, "stove");
  EXPECT_EQ(back.affordances.size(), 2u);
  press(session, GLFW_KEY_3, GLFW_MOD_SHIFT);
  EXPECT_EQ(readLabels(labels).object.category, "none");
}

TEST(CategoryKeys, OnlyShiftWithTheFirstThreeDigitsSwitches) {
  const fs::path labels = writeStove(test::freshTempDir() / "stove", false);
  Session session;
  session.autoPredict = false;
  session.openPaths({labels.parent_path()});
  press(session, GLFW_KEY_4, GLFW_MOD_SHIFT);  // no fourth category with a key
  press(session, GLFW_KEY_2, 0);               // a type, not a category
  const ObjectLabels kept = readLabels(labels);
  EXPECT_EQ(kept.object.category, "stove");
  EXPECT_EQ(kept.affordances.size(), 2u);
  EXPECT_EQ(session.currentType(), "togglebutton");
}

TEST(CategoryKeys, TheSuggestedCategorysKeyTakesItWithItsPointsAsCDoes) {
  const fs::path dir = test::freshTempDir();
  const fs::path labels = writeStove(dir / "stove", true);
  Session session;
  session.autoPredict = false;
  session.setCurationLog(dir / "curation.jsonl");
  session.openPaths({labels.parent_path()});
  press(session, GLFW_KEY_1, GLFW_MOD_SHIFT);
  const ObjectLabels taken = readLabels(labels);
  EXPECT_EQ(taken.object.category, "stove");
  ASSERT_EQ(taken.affordances.size(), 2u);
  EXPECT_FALSE(isSuggestion(taken.affordances[0]));
  EXPECT_EQ(test::loggedActions(dir / "curation.jsonl", CurationAction::ConfirmCategory), 1);
}

TEST(CategoryKeys, TheCuratorsPlanSwitchesByKeyWhereTheCategoryHasOneAndTheKeyCostsLess) {
  ObjectLabels opened;
  opened.object.category = "sink";
  ObjectLabels truth;
  truth.object.category = "stove";
  const auto byKey = curationPlan(opened, truth);
  ASSERT_EQ(byKey.size(), 1u);
  EXPECT_EQ(byKey[0].action, CurationAction::CategoryKey);
  EXPECT_EQ(byKey[0].category, "stove");
  truth.object.category = "microwave";  // no key: the list
  const auto byList = curationPlan(opened, truth);
  ASSERT_EQ(byList.size(), 1u);
  EXPECT_EQ(byList[0].action, CurationAction::Category);
  EXPECT_LT(klmSeconds(CurationAction::CategoryKey, KlmOperators{}),
            klmSeconds(CurationAction::Category, KlmOperators{}));
  EXPECT_EQ(parseCurationAction("category_key"), CurationAction::CategoryKey);
}

}  // namespace
}  // namespace sagrid::ui
