// The extend action (E): a point one step past the selected one along its row, for rows the
// copies action cannot carry (keys printed on a glass top, knobs fused into the panel); one
// undoable step, logged as "extend"; the replayed curator uses it after an addition where it
// replaces further additions.
#include "ui/document/point_row.h"

#include <gtest/gtest.h>

#include "core/curation/curation_report.h"
#include "support/analytic_meshes.h"
#include "support/curation_counts.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"
#include "ui/app/curation_replay.h"
#include "ui/app/session.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// A flat top (0.5 x 0.5 x 0.1 m) with five keys printed in a row on it (x = -0.2 .. 0.2, a
// tenth apart) and two zones: only a texture would show them, so no part is theirs to copy.
std::vector<AffordancePoint> printedHob() {
  std::vector<AffordancePoint> points;
  for (float x : {-0.15f, 0.15f})
    points.push_back(test::affordance("heatsource", {x, 0.05f, 0.1f}));
  for (int k = 0; k < 5; ++k)
    points.push_back(test::affordance("togglebutton", {-0.2f + 0.1f * float(k), -0.2f, 0.1f}));
  return points;
}

// The hob opened with its zones and the first `keys` keys, in a session that logs to
// dir/curation.jsonl.
class PointRow : public ::testing::Test {
 protected:
  void open(int keys) {
    truth.affordances = printedHob();
    std::vector<AffordancePoint> opened(truth.affordances.begin(),
                                        truth.affordances.begin() + 2 + keys);
    test::writeLabelledObject(dir / "queue" / "hob",
                              test::box({-0.25f, -0.25f, 0.0f}, {0.25f, 0.25f, 0.1f}), opened,
                              "printed_hob", "stove");
    truth.object = readLabels(dir / "queue" / "hob" / "labels.json").object;
    session.autoPredict = false;
    session.logErrors = false;
    session.setCurationLog(dir / "curation.jsonl");
    session.openPaths({dir / "queue"});
    ASSERT_TRUE(session.document());
  }
  std::ptrdiff_t logged(CurationAction action) const {
    return test::loggedActions(dir / "curation.jsonl", action);
  }
  const fs::path dir = test::freshTempDir();
  ObjectLabels truth;
  Session session;
};

TEST_F(PointRow, TwoKeysExtendToTheRowsEndOneUndoableStepEachAndNoFarther) {
  open(2);
  EXPECT_FALSE(session.extendRowOfSelected());  // nothing selected
  session.document()->select(3);                // the second key
  for (int k = 2; k < 5; ++k) {
    const std::size_t steps = session.document()->historySize();
    ASSERT_TRUE(session.extendRowOfSelected()) << k;
    EXPECT_EQ(session.document()->historySize(), steps + 1);
    const AffordancePoint& added = session.document()->points().back();
    EXPECT_EQ(added.type, "togglebutton");
    EXPECT_EQ(added.status, AffordanceStatus::Added);
    EXPECT_LT((added.position - truth.affordances[std::size_t(2 + k)].position).norm(), 1e-4f) << k;
    ASSERT_TRUE(added.normal);
    EXPECT_GT(added.normal->z(), 0.99f);  // the top's normal
    // The point added is selected: E again goes on.
    EXPECT_EQ(session.document()->selected(),
              static_cast<int>(session.document()->points().size()) - 1);
  }
  // One step past the fifth key is off the top (5 cm beyond its edge): nothing, one message.
  EXPECT_FALSE(session.extendRowOfSelected());
  EXPECT_FALSE(session.pendingErrors().empty());
  EXPECT_EQ(test::countOfType(session.document()->points(), "togglebutton"), 5u);
  EXPECT_EQ(logged(CurationAction::Extend), 3);
  session.undo();
  EXPECT_EQ(test::countOfType(session.document()->points(), "togglebutton"), 4u);
}

TEST_F(PointRow, ALonePointOrAStepOntoAPointOfItsTypeAddsNothing) {
  open(3);
  // The zones: each the other's nearest, a step past either is off the top (x = +-0.45).
  session.document()->select(0);
  EXPECT_FALSE(nextPointInRow(*session.document(), 0));
  // The middle key: its nearest is a key a tenth away, and one step on is the other key.
  EXPECT_FALSE(nextPointInRow(*session.document(), 3));
  // The third key extends to the fourth.
  const auto next = nextPointInRow(*session.document(), 4);
  ASSERT_TRUE(next);
  EXPECT_LT((next->position - truth.affordances[5].position).norm(), 1e-4f);
  EXPECT_FALSE(nextPointInRow(*session.document(), 99));
  EXPECT_FALSE(nextPointInRow(*session.document(), -1));
}

TEST_F(PointRow, TheReplayedCuratorExtendsARowAfterPlacingTwoOfItsPoints) {
  open(0);
  const auto summary = replayCuration(
      session, [&](const std::string&) -> std::optional<ObjectLabels> { return truth; });
  EXPECT_EQ(summary.objects, 1u);
  const ObjectLabels done = readLabels(dir / "queue" / "hob" / "labels.json");
  EXPECT_EQ(test::countOfType(done.affordances, "togglebutton"), 5u);
  const CurationReport report = curationReport(readCurationLog(dir / "curation.jsonl"));
  ASSERT_EQ(report.objects.size(), 1u);
  EXPECT_EQ(report.objects[0].edits, 5);  // two additions, three extensions
  EXPECT_EQ(report.objects[0].actions.at(CurationAction::Add), 2);
  EXPECT_EQ(report.objects[0].actions.at(CurationAction::Extend), 3);
  // An extension is a key on the point just placed: cheaper than an addition by KLM.
  EXPECT_LT(klmSeconds(CurationAction::Extend), klmSeconds(CurationAction::Add));
}

// The right labels list the keys out of their row's order (3, 1, 5, 2, 4): the curator still
// places two neighbours of the row by hand and extends to the rest.
TEST_F(PointRow, TheReplayedCuratorPlacesTwoNeighboursFirstWhateverTheLabelsOrder) {
  open(0);
  const std::vector<AffordancePoint> keys(truth.affordances.begin() + 2, truth.affordances.end());
  truth.affordances.resize(2);
  for (int k : {2, 0, 4, 1, 3}) truth.affordances.push_back(keys[std::size_t(k)]);
  replayCuration(session, [&](const std::string&) -> std::optional<ObjectLabels> { return truth; });
  const CurationReport report = curationReport(readCurationLog(dir / "curation.jsonl"));
  ASSERT_EQ(report.objects.size(), 1u);
  EXPECT_EQ(report.objects[0].actions.at(CurationAction::Add), 2);
  EXPECT_EQ(report.objects[0].actions.at(CurationAction::Extend), 3);
  const ObjectLabels done = readLabels(dir / "queue" / "hob" / "labels.json");
  for (const AffordancePoint& key : keys) {
    float nearest = 1e9f;
    for (const AffordancePoint& p : done.affordances)
      if (p.type == key.type) nearest = std::min(nearest, (p.position - key.position).norm());
    EXPECT_LT(nearest, 1e-4f);
  }
}

}  // namespace
}  // namespace sagrid::ui
