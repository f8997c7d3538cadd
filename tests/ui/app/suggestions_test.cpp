// A rejected object's suggested points in the GUI session: C takes the suggested category with
// them (one undoable step), A keeps "none" and drops them; the replayed curator's plan does the
// same.
#include <gtest/gtest.h>

#include "core/annotate/suggested_points.h"
#include "core/curation/curation_plan.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"
#include "ui/app/session.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

fs::path rejectedStove(const fs::path& dir) { return test::writeTinyStove(dir, true); }

TEST(Suggestions, CTakesTheSuggestedCategoryWithItsPointsAndUndoGivesThemBack) {
  const fs::path labels = rejectedStove(test::freshTempDir() / "stove");
  Session session;
  session.autoPredict = false;
  session.openPaths({labels.parent_path()});
  session.confirmSuggestedCategory();
  const ObjectLabels taken = readLabels(labels);
  EXPECT_EQ(taken.object.category, "stove");
  ASSERT_EQ(taken.affordances.size(), 2u);
  EXPECT_FALSE(isSuggestion(taken.affordances[0]));
  EXPECT_FALSE(suggestedCategory(taken));
  session.undo();
  EXPECT_EQ(readLabels(labels).object.category, "none");
  EXPECT_TRUE(isSuggestion(readLabels(labels).affordances[0]));
}

TEST(Suggestions, NumberKeysFollowTheSuggestedCategoryOfAnObjectJudgedNone) {
  const fs::path labels = rejectedStove(test::freshTempDir() / "stove");
  Session session;
  session.autoPredict = false;
  session.openPaths({labels.parent_path()});
  const auto types = session.typesForKeys();
  ASSERT_GE(types.size(), 2u);
  EXPECT_EQ(types[0], "heatsource");
  EXPECT_EQ(types[1], "togglebutton");  // 2 is a knob, as on a stove
}

TEST(Suggestions, AcceptingKeepsNoneAndDropsThem) {
  const fs::path labels = rejectedStove(test::freshTempDir() / "stove");
  Session session;
  session.autoPredict = false;
  session.openPaths({labels.parent_path()});
  session.accept();
  const ObjectLabels kept = readLabels(labels);
  EXPECT_EQ(kept.object.category, "none");
  EXPECT_TRUE(kept.affordances.empty());
  EXPECT_EQ(kept.reviewState, ReviewState::Done);
}

TEST(Suggestions, TheCuratorsPlanTakesThemWithOneKeyOrLetsAcceptDropThem) {
  const ObjectLabels opened = readLabels(rejectedStove(test::freshTempDir() / "stove"));
  ObjectLabels stove;
  stove.object.category = "stove";
  stove.affordances = opened.affordances;
  const auto take = curationPlan(opened, stove);
  ASSERT_EQ(take.size(), 1u);
  EXPECT_EQ(take[0].action, CurationAction::ConfirmCategory);
  ObjectLabels none;
  none.object.category = "none";
  EXPECT_TRUE(curationPlan(opened, none).empty());
}

}  // namespace
}  // namespace sagrid::ui
