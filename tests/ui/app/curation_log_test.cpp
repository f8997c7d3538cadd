// The GUI's curation log: what a curator does in the viewport and with keys reaches the log as
// actions of the open object, and the report reads them back.
#include <gtest/gtest.h>

#include "core/curation/curation_report.h"
#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"

namespace sagrid::ui {
namespace {

using test::ScriptedApp;

TEST(CurationLogInGui, LookDragUndoAndAcceptAllAreLoggedForTheObject) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  const auto log = dir / "curation.jsonl";
  s.app->session().setCurationLog(log);
  s.drag({30.0f, 30.0f}, {90.0f, 50.0f});  // an orbit, from a corner far from every point
  s.drag(s.pixelOf({-0.2f, 0.2f, 0.0f}), s.pixelOf({0.25f, -0.25f, 0.2f}));
  s.key(GLFW_KEY_Z, GLFW_MOD_CONTROL);
  s.key(GLFW_KEY_ESCAPE);
  s.key(GLFW_KEY_A);
  const std::vector<CurationEvent> events = readCurationLog(log);
  std::vector<CurationAction> actions;
  for (const auto& e : events) actions.push_back(e.action);
  const std::vector<CurationAction> expected{CurationAction::Look, CurationAction::Drag, CurationAction::Undo,
                                             CurationAction::AcceptAll};
  EXPECT_EQ(actions, expected);
  const CurationReport report = curationReport(events);
  ASSERT_EQ(report.objects.size(), 1u);
  EXPECT_EQ(report.objects[0].edits, 1);
  EXPECT_FALSE(report.objects[0].oneKey);
}

}  // namespace
}  // namespace sagrid::ui
