// The copies action (R): one knob's point carried onto the other knobs of its row in one undoable
// step, logged as "copies"; the replayed curator uses it where it saves actions.
#include "ui/document/point_copies.h"

#include <gtest/gtest.h>

#include "core/curation/curation_report.h"
#include "support/curation_counts.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"
#include "ui/app/curation_replay.h"
#include "ui/app/session.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// The analytic stove (four knobs in a row on its front) opened with its burners and one knob.
ObjectLabels stoveWithOneKnob(const fs::path& dir, ObjectLabels* truth) {
  const fs::path labels = test::writeAnalyticStove(dir);
  ObjectLabels all = readLabels(labels);
  if (truth) *truth = all;
  ObjectLabels one = all;
  one.affordances.erase(one.affordances.begin() + 5, one.affordances.end());  // 4 burners, 1 knob
  writeLabels(labels, one);
  return one;
}

// The stove opened in a session that logs to dir/curation.jsonl; `truth` its right labels.
class PointCopies : public ::testing::Test {
 protected:
  void SetUp() override {
    stoveWithOneKnob(dir / "queue" / "stove", &truth);
    session.autoPredict = false;
    session.logErrors = false;
    session.setCurationLog(dir / "curation.jsonl");
    session.openPaths({dir / "queue"});
  }
  std::ptrdiff_t logged(CurationAction action) const {
    return test::loggedActions(dir / "curation.jsonl", action);
  }
  const fs::path dir = test::freshTempDir();
  ObjectLabels truth;
  Session session;
};

TEST_F(PointCopies, OneKnobsPointGoesOntoEveryOtherKnobInOneUndoableStep) {
  ASSERT_TRUE(session.document());
  EXPECT_EQ(session.addOnCopiesOfSelected(), 0);  // nothing selected
  session.document()->select(4);                  // the knob
  const std::size_t steps = session.document()->historySize();
  ASSERT_EQ(session.addOnCopiesOfSelected(), 3);
  EXPECT_EQ(session.document()->historySize(), steps + 1);
  const auto& points = session.document()->points();
  ASSERT_EQ(test::countOfType(points, "togglebutton"), 4u);
  // Each truth knob has a point within a millimetre, each added "added".
  for (const auto& t : truth.affordances) {
    if (t.type != "togglebutton") continue;
    float nearest = 1e9f;
    for (const auto& p : points)
      if (p.type == "togglebutton") nearest = std::min(nearest, (p.position - t.position).norm());
    EXPECT_LT(nearest, 1e-3f);
  }
  EXPECT_EQ(points.back().status, AffordanceStatus::Added);
  // Again: every copy holds a knob's point now, nothing added, one message.
  session.document()->select(4);
  EXPECT_EQ(session.addOnCopiesOfSelected(), 0);
  EXPECT_FALSE(session.pendingErrors().empty());
  session.undo();
  EXPECT_EQ(test::countOfType(session.document()->points(), "togglebutton"), 1u);
  EXPECT_EQ(logged(CurationAction::Copies), 1);
  // A burner has no copy on this mesh (burners are drawn, not modelled): nothing, one message.
  session.document()->select(0);
  EXPECT_EQ(session.addOnCopiesOfSelected(), 0);
}

// Shift+Del: the selected point and every later point of its type go in one undoable step,
// logged as "delete_rest"; the other types' points stay.
TEST_F(PointCopies, DeleteRestTakesTheSelectedPointAndItsTypesLaterOnesInOneStep) {
  ASSERT_TRUE(session.document());
  EXPECT_EQ(session.deleteRestOfSelected(), 0);  // nothing selected
  const std::vector<AffordancePoint> before = session.document()->points();
  ASSERT_EQ(test::countOfType(before, "heatsource"), 4u);
  session.document()->select(1);  // the second burner: it and the two after it go
  const std::size_t steps = session.document()->historySize();
  EXPECT_EQ(session.deleteRestOfSelected(), 3);
  EXPECT_EQ(session.document()->historySize(), steps + 1);
  const auto& after = session.document()->points();
  EXPECT_EQ(test::countOfType(after, "heatsource"), 1u);
  EXPECT_EQ(test::countOfType(after, "togglebutton"), 1u);
  EXPECT_EQ(after.front().position, before.front().position);
  session.undo();
  ASSERT_EQ(session.document()->points().size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i)
    EXPECT_EQ(session.document()->points()[i].position, before[i].position) << i;
  EXPECT_EQ(logged(CurationAction::DeleteRest), 1);
}

TEST_F(PointCopies, TheReplayedCuratorTakesCopiesWhereTheyReplaceAdds) {
  const auto summary = replayCuration(
      session, [&](const std::string&) -> std::optional<ObjectLabels> { return truth; });
  EXPECT_EQ(summary.objects, 1u);
  const ObjectLabels done = readLabels(dir / "queue" / "stove" / "labels.json");
  EXPECT_EQ(test::countOfType(done.affordances, "togglebutton"), 4u);
  const CurationReport report = curationReport(readCurationLog(dir / "curation.jsonl"));
  ASSERT_EQ(report.objects.size(), 1u);
  EXPECT_EQ(report.objects[0].edits, 1);  // one copies action instead of three adds
  EXPECT_EQ(report.objects[0].actions.at(CurationAction::Copies), 1);
  EXPECT_EQ(report.objects[0].actions.count(CurationAction::Add), 0u);
}

}  // namespace
}  // namespace sagrid::ui
