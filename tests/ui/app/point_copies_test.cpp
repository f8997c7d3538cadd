// The copies action (R): one knob's point carried onto the other knobs of its row in one undoable
// step, logged as "copies"; the replayed curator uses it where it saves actions.
#include "ui/document/point_copies.h"

#include <gtest/gtest.h>

#include "core/curation/curation_report.h"
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

std::size_t countOf(const std::vector<AffordancePoint>& points, const std::string& type) {
  return static_cast<std::size_t>(std::count_if(
      points.begin(), points.end(), [&](const AffordancePoint& p) { return p.type == type; }));
}

// The stove opened in a session that logs to dir/curation.jsonl; `truth` its right labels.
void openStove(Session& session, const fs::path& dir, ObjectLabels& truth) {
  stoveWithOneKnob(dir / "queue" / "stove", &truth);
  session.autoPredict = false;
  session.logErrors = false;
  session.setCurationLog(dir / "curation.jsonl");
  session.openPaths({dir / "queue"});
}

TEST(PointCopies, OneKnobsPointGoesOntoEveryOtherKnobInOneUndoableStep) {
  const fs::path dir = test::freshTempDir();
  ObjectLabels truth;
  Session session;
  openStove(session, dir, truth);
  ASSERT_TRUE(session.document());
  EXPECT_EQ(session.addOnCopiesOfSelected(), 0);  // nothing selected
  session.document()->select(4);                  // the knob
  const std::size_t steps = session.document()->historySize();
  ASSERT_EQ(session.addOnCopiesOfSelected(), 3);
  EXPECT_EQ(session.document()->historySize(), steps + 1);
  const auto& points = session.document()->points();
  ASSERT_EQ(countOf(points, "togglebutton"), 4u);
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
  EXPECT_EQ(countOf(session.document()->points(), "togglebutton"), 1u);
  const auto events = readCurationLog(dir / "curation.jsonl");
  EXPECT_EQ(std::count_if(events.begin(), events.end(),
                          [](const CurationEvent& e) { return e.action == CurationAction::Copies; }),
            1);
  // A burner has no copy on this mesh (burners are drawn, not modelled): nothing, one message.
  session.document()->select(0);
  EXPECT_EQ(session.addOnCopiesOfSelected(), 0);
}

TEST(PointCopies, TheReplayedCuratorTakesCopiesWhereTheyReplaceAdds) {
  const fs::path dir = test::freshTempDir();
  ObjectLabels truth;
  Session session;
  openStove(session, dir, truth);
  const auto summary = replayCuration(
      session, [&](const std::string&) -> std::optional<ObjectLabels> { return truth; });
  EXPECT_EQ(summary.objects, 1u);
  const ObjectLabels done = readLabels(dir / "queue" / "stove" / "labels.json");
  EXPECT_EQ(countOf(done.affordances, "togglebutton"), 4u);
  const CurationReport report = curationReport(readCurationLog(dir / "curation.jsonl"));
  ASSERT_EQ(report.objects.size(), 1u);
  EXPECT_EQ(report.objects[0].edits, 1);  // one copies action instead of three adds
  EXPECT_EQ(report.objects[0].actions.at(CurationAction::Copies), 1);
  EXPECT_EQ(report.objects[0].actions.count(CurationAction::Add), 0u);
}

}  // namespace
}  // namespace sagrid::ui
