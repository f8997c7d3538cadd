// The object's category by its own key (Shift+1 stove, Shift+2 sink, Shift+3 none): the same
// undoable switch as the Object panel's list, logged as `category_key`, which the keystroke-level
// model counts as a key instead of a trip to the list; the replayed curator's plan uses it.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/annotate/suggested_points.h"
#include "core/curation/curation_plan.h"
#include "core/curation/curation_report.h"
#include "support/curation_counts.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"
#include "ui/app/session.h"
#include "ui/app/shortcuts.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// The tiny stove (or, rejected, filed as "none" with its points suggested) open in a session that
// logs its curation.
struct OpenStove {
  explicit OpenStove(bool rejected)
      : dir(test::freshTempDir()), labels(test::writeTinyStove(dir / "stove", rejected)) {
    session.autoPredict = false;
    session.setCurationLog(dir / "curation.jsonl");
    session.openPaths({labels.parent_path()});
  }
  void press(int key, int mods) { handleShortcuts({InputEvent::keyEvent(key, true, mods)}, session, false); }
  std::ptrdiff_t logged(CurationAction action) const { return test::loggedActions(dir / "curation.jsonl", action); }

  fs::path dir;
  fs::path labels;
  Session session;
};

TEST(CategoryKeys, ShiftTwoFilesAStoveAsASinkInOneUndoableStepLoggedAsTheKey) {
  OpenStove open(false);
  open.press(GLFW_KEY_2, GLFW_MOD_SHIFT);
  const ObjectLabels switched = readLabels(open.labels);
  EXPECT_EQ(switched.object.category, "sink");
  EXPECT_TRUE(switched.affordances.empty());  // the stove's predicted points go with its category
  EXPECT_EQ(open.logged(CurationAction::CategoryKey), 1);
  EXPECT_EQ(open.logged(CurationAction::Category), 0);
  open.session.undo();
  const ObjectLabels back = readLabels(open.labels);
  EXPECT_EQ(back.object.category, "stove");
  EXPECT_EQ(back.affordances.size(), 2u);
  open.press(GLFW_KEY_3, GLFW_MOD_SHIFT);
  EXPECT_EQ(readLabels(open.labels).object.category, "none");
}

TEST(CategoryKeys, OnlyShiftWithTheFirstThreeDigitsSwitches) {
  OpenStove open(false);
  open.press(GLFW_KEY_4, GLFW_MOD_SHIFT);  // no fourth category with a key
  open.press(GLFW_KEY_2, 0);               // a type, not a category
  const ObjectLabels kept = readLabels(open.labels);
  EXPECT_EQ(kept.object.category, "stove");
  EXPECT_EQ(kept.affordances.size(), 2u);
  EXPECT_EQ(open.session.currentType(), "togglebutton");
  EXPECT_EQ(open.logged(CurationAction::CategoryKey), 0);
}

TEST(CategoryKeys, TheSuggestedCategorysKeyTakesItWithItsPointsAsCDoes) {
  OpenStove open(true);
  open.press(GLFW_KEY_1, GLFW_MOD_SHIFT);
  const ObjectLabels taken = readLabels(open.labels);
  EXPECT_EQ(taken.object.category, "stove");
  ASSERT_EQ(taken.affordances.size(), 2u);
  EXPECT_FALSE(isSuggestion(taken.affordances[0]));
  EXPECT_EQ(open.logged(CurationAction::ConfirmCategory), 1);
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
