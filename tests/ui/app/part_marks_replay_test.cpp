// Hand-marked control parts replayed through the GUI session: a kept part and a brushed one end
// confirmed in labels.json on disk with the axis the marks give; marks that cannot apply are named;
// a malformed marks file is one error naming it.
#include "ui/app/part_marks_replay.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/common/error.h"
#include "core/controls/control_record.h"
#include "support/test_paths.h"
#include "ui/app/control_edit.h"
#include "ui/app/session.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// labels.json of a z-up stove whose mesh is mesh.obj, with `points`.
void writeStoveLabels(const fs::path& dir, std::vector<AffordancePoint> points) {
  ObjectLabels labels;
  labels.object.id = dir.filename().string();
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  labels.object.up = "z";
  labels.affordances = std::move(points);
  writeLabels(dir / "labels.json", labels);
}

// A 1 m plate with a separate 30 x 30 x 20 cm block on it; toggle buttons on the block's top and
// on the plate's corner, a heat source in between.
void writeObject(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream obj(dir / "mesh.obj");
  obj << "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nf 1 2 3\nf 1 3 4\n"
         "v 0.1 -0.4 0.2\nv 0.4 -0.4 0.2\nv 0.4 -0.1 0.2\nv 0.1 -0.1 0.2\n"
         "v 0.1 -0.4 0\nv 0.4 -0.4 0\nv 0.4 -0.1 0\nv 0.1 -0.1 0\n"
         "f 5 6 7\nf 5 7 8\nf 9 10 6\nf 9 6 5\nf 10 11 7\nf 10 7 6\nf 11 12 8\nf 11 8 7\nf 12 9 5\nf 12 5 8\n";
  obj.close();
  AffordancePoint knob, corner, heat;
  knob.type = corner.type = "togglebutton";
  knob.position = {0.25f, -0.25f, 0.2f};
  corner.position = {-0.45f, 0.45f, 0.0f};
  heat.type = "heatsource";
  writeStoveLabels(dir, {knob, heat, corner});
}

// The session without predictions, its queue the object folders in `queue`.
void openQueue(Session& session, const fs::path& queue) {
  session.autoPredict = false;
  session.openPaths({queue});
}

std::optional<ControlRecord> recordOf(const fs::path& dir, int index) {
  const ObjectLabels labels = readLabels(dir / "labels.json");
  return readControlRecord(labels.affordances[std::size_t(index)], UpAxis::Z, dir / "labels.json");
}

TEST(PartMarksReplay, KeptAndBrushedPartsEndConfirmedOnDiskWithTheirAxes) {
  const fs::path dir = test::freshTempDir();
  writeObject(dir / "queue" / "a");
  writeObject(dir / "queue" / "b");
  writeObject(dir / "queue" / "c");  // not in the marks: untouched
  const auto marks = nlohmann::json::parse(R"({"objects": {
    "a": [{"point": 1, "keep": true, "axis": "x"}],
    "b": [{"point": 1, "strokes": [{"at": [0.25, -0.25, 0.2], "radius_cm": 1, "mode": "replace"}]},
          {"point": 2, "keep": true}, {"point": 3, "strokes": [{"at": [-0.45, 0.45, 0], "radius_cm": 1}]}],
    "nowhere": [{"point": 1, "keep": true}]}})");
  Session session;
  session.autoPredict = false;
  session.setCurationLog(dir / "curation.jsonl");
  session.openPaths({dir / "queue"});
  const PartMarksSummary summary = replayPartMarks(session, marks, "marks.json");
  EXPECT_EQ(summary.objects, 2u);
  // Point 2 of b is a heat source, "nowhere" was not opened: both named, nothing marked.
  ASSERT_EQ(summary.problems.size(), 2u);
  EXPECT_NE(summary.problems[0].find("b point 2"), std::string::npos) << summary.problems[0];
  EXPECT_NE(summary.problems[1].find("nowhere: no such object"), std::string::npos) << summary.problems[1];

  const auto kept = recordOf(dir / "queue" / "a", 0);
  ASSERT_TRUE(kept);
  EXPECT_TRUE(kept->confirmed);
  EXPECT_FALSE(kept->part.triangles.empty());  // as found, not marked
  EXPECT_NE(kept->part.origin, PartOrigin::Marked);
  EXPECT_TRUE(kept->part.axis.isApprox(Eigen::Vector3f::UnitX()));
  const auto brushed = recordOf(dir / "queue" / "b", 0);
  ASSERT_TRUE(brushed);
  EXPECT_TRUE(brushed->confirmed);
  EXPECT_EQ(brushed->part.origin, PartOrigin::Marked);
  EXPECT_EQ(brushed->part.triangles.size(), 1u);  // a 1 cm brush: the clicked triangle alone
  // A toggle button without a part gets one brushed on: the plate's corner triangle.
  const auto corner = recordOf(dir / "queue" / "b", 2);
  ASSERT_TRUE(corner);
  EXPECT_EQ(corner->part.triangles.size(), 1u);
  EXPECT_FALSE(recordOf(dir / "queue" / "c", 0));

  // A stroke of an unknown mode: one error naming the marks file.
  writeObject(dir / "again" / "a");
  Session other;
  other.autoPredict = false;
  other.openPaths({dir / "again"});
  const auto bad = nlohmann::json::parse(
      R"({"objects": {"a": [{"point": 1, "strokes": [{"at": [0.25, -0.25, 0.2], "mode": "smear"}]}]}})");
  try {
    replayPartMarks(other, bad, "marks.json");
    FAIL() << "an unknown mode was replayed";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("marks.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("smear"), std::string::npos) << e.what();
  }
  EXPECT_THROW(replayPartMarks(other, nlohmann::json::parse("[1]"), "marks.json"), FileError);
  // A radius that is no radius, a point that is no whole number: named with the object.
  const std::vector<std::pair<const char*, const char*>> malformed{
      {R"({"objects": {"a": [{"point": 1, "strokes": [{"at": [0.25, -0.25, 0.2], "radius_cm": -1}]}]}})",
       "a point 1: a stroke's radius_cm"},
      {R"({"objects": {"a": [{"point": 1.5, "keep": true}]}})", "object a: a mark needs \"point\""}};
  for (const auto& [text, message] : malformed) {
    try {
      replayPartMarks(other, nlohmann::json::parse(text), "marks.json");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("marks.json"), std::string::npos) << e.what();
    }
  }
}

// Keep all and This axis for all: every control of the object (that moves as the given one does)
// in one undo step, as the Points panel's buttons do.
TEST(PartMarksReplay, KeepAllAndOneAxisForAllAreOneStepEach) {
  const fs::path dir = test::freshTempDir();
  writeObject(dir / "queue" / "a");
  Session session;
  openQueue(session, dir / "queue");
  const auto marks = nlohmann::json::parse(R"({"objects": {"a": [{"keep_all": true}]}})");
  const PartMarksSummary kept = replayPartMarks(session, marks, "marks.json");
  EXPECT_TRUE(kept.problems.empty());
  const auto first = recordOf(dir / "queue" / "a", 0);
  ASSERT_TRUE(first);
  EXPECT_TRUE(first->confirmed);
  const std::size_t steps = session.document()->historySize();
  EXPECT_EQ(kept.parts, 2u);  // both toggle buttons show a control
  // Those moving as point 1 does (not the corner's disc), in one more step.
  const std::size_t alike = confirmEveryControl(session, 0);
  EXPECT_GE(alike, 1u);
  EXPECT_LE(alike, kept.parts);
  EXPECT_EQ(session.document()->historySize(), steps + 1);
  session.undo();
  session.undo();
  EXPECT_FALSE(recordOf(dir / "queue" / "a", 0));  // Keep all undone in one step
  const auto axis = nlohmann::json::parse(
      R"({"objects": {"a": [{"point": 1, "axis": "y", "for_all": true}]}})");
  replayPartMarks(session, axis, "marks.json");
  EXPECT_TRUE(recordOf(dir / "queue" / "a", 0)->part.axis.isApprox(Eigen::Vector3f::UnitY()));
}

// A 1 m plate with a round knob (4 cm across, 2 cm tall, 32 sides) leaning 20 degrees about x,
// as on a sloped control panel, held 3 mm above the plate at its lowest; one toggle button on its
// top.
void writeLeaningKnob(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream obj(dir / "mesh.obj");
  obj << "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nf 1 2 3\nf 1 3 4\n";
  const double lean = 20.0 * M_PI / 180.0;
  const auto vertex = [&](double x, double y, double z) {  // turned about x, raised 1 cm
    obj << "v " << x << " " << y * std::cos(lean) - z * std::sin(lean) << " "
        << y * std::sin(lean) + z * std::cos(lean) + 0.01 << "\n";
  };
  const int n = 32;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < n; ++i)
      vertex(0.02 * std::cos(2 * M_PI * i / n), 0.02 * std::sin(2 * M_PI * i / n), 0.02 * k);
  vertex(0, 0, 0);
  vertex(0, 0, 0.02);
  for (int i = 0; i < n; ++i) {  // OBJ indices after the plate's 4
    const int a = 5 + i, b = 5 + (i + 1) % n, c = 5 + n + (i + 1) % n, d = 5 + n + i;
    obj << "f " << a << " " << b << " " << c << "\nf " << a << " " << c << " " << d << "\n"
        << "f " << 5 + 2 * n << " " << b << " " << a << "\nf " << 6 + 2 * n << " " << d << " " << c << "\n";
  }
  obj.close();
  AffordancePoint knob;
  knob.type = "togglebutton";
  knob.position = {0.0f, static_cast<float>(-0.02 * std::sin(lean)),
                   static_cast<float>(0.02 * std::cos(lean) + 0.01)};
  writeStoveLabels(dir, {knob});
}

// "own": the knob's axis of rotational symmetry, leaning with it, in one undoable step; refused
// for a lever until the mark makes it a knob.
TEST(PartMarksReplay, AKnobGetsItsOwnLeaningAxisInOneStep) {
  const fs::path dir = test::freshTempDir();
  writeLeaningKnob(dir / "queue" / "a");
  Session session;
  openQueue(session, dir / "queue");
  const auto marks = nlohmann::json::parse(R"({"objects": {"a": [{"point": 1, "axis": "z"}]}})");
  replayPartMarks(session, marks, "marks.json");
  ASSERT_TRUE(recordOf(dir / "queue" / "a", 0));
  const std::size_t steps = session.document()->historySize();
  ASSERT_TRUE(setOwnAxis(session, 0));
  EXPECT_EQ(session.document()->historySize(), steps + 1);
  const Eigen::Vector3f leaning(0.0f, -std::sin(20.0f * static_cast<float>(M_PI) / 180.0f),
                                std::cos(20.0f * static_cast<float>(M_PI) / 180.0f));
  const auto own = recordOf(dir / "queue" / "a", 0);
  ASSERT_TRUE(own);
  EXPECT_GT(own->part.axis.dot(leaning), std::cos(2.0f * static_cast<float>(M_PI) / 180.0f));
  session.undo();
  EXPECT_TRUE(recordOf(dir / "queue" / "a", 0)->part.axis.isApprox(Eigen::Vector3f::UnitZ()));
  // The same from a marks file.
  replayPartMarks(session, nlohmann::json::parse(R"({"objects": {"a": [{"point": 1, "axis": "own"}]}})"),
                  "marks.json");
  EXPECT_GT(recordOf(dir / "queue" / "a", 0)->part.axis.dot(leaning), 0.999f);
  // Not a knob's: "own" names the control it cannot apply to, and changes nothing.
  const std::size_t before = session.document()->historySize();
  const PartMarksSummary lever = replayPartMarks(
      session, nlohmann::json::parse(R"({"objects": {"a": [{"point": 1, "axis": "x"}]}})"), "marks.json");
  EXPECT_TRUE(lever.problems.empty());
  ShownControl asLever = *shownControl(*session.document(), 0);
  asLever.part.motion = ControlMotion::Lever;
  asLever.part.pivot += Eigen::Vector3f(0.01f, 0.0f, 0.0f);  // a lever's held end
  setControlRecord(session, 0, asLever, "moves as a lever");
  EXPECT_FALSE(setOwnAxis(session, 0));
  const PartMarksSummary refused = replayPartMarks(
      session, nlohmann::json::parse(R"({"objects": {"a": [{"point": 1, "axis": "own"}]}})"), "marks.json");
  ASSERT_EQ(refused.problems.size(), 1u);
  EXPECT_NE(refused.problems[0].find("is a knob's axis"), std::string::npos) << refused.problems[0];
  EXPECT_EQ(session.document()->historySize(), before + 2);  // the x axis and the lever only
  // Marked a knob first (the Points panel's motion list), it takes its own axis: two steps.
  const PartMarksSummary asKnob = replayPartMarks(
      session, nlohmann::json::parse(R"({"objects": {"a": [{"point": 1, "motion": "knob", "axis": "own"}]}})"),
      "marks.json");
  EXPECT_TRUE(asKnob.problems.empty());
  const auto knob = recordOf(dir / "queue" / "a", 0);
  ASSERT_TRUE(knob);
  EXPECT_EQ(knob->part.motion, ControlMotion::Knob);
  EXPECT_GT(std::abs(knob->part.axis.dot(leaning)), 0.999f);  // facing the way the x axis did
  EXPECT_EQ(session.document()->historySize(), before + 4);
  // A knob turns about its middle, not the lever's held end.
  EXPECT_TRUE(knob->part.pivot.isApprox(partCentre(session.document()->mesh(), knob->part.triangles), 1e-4f))
      << knob->part.pivot.transpose();
  EXPECT_THROW(replayPartMarks(session,
                               nlohmann::json::parse(R"({"objects": {"a": [{"point": 1, "motion": "slider"}]}})"),
                               "marks.json"),
               FileError);
}

// A mark that only names the motion the found control already has still confirms it, as Keep does.
TEST(PartMarksReplay, AMotionMarkConfirmsAControlThatAlreadyMovesSo) {
  const fs::path dir = test::freshTempDir();
  writeLeaningKnob(dir / "queue" / "a");
  Session session;
  openQueue(session, dir / "queue");
  EXPECT_FALSE(recordOf(dir / "queue" / "a", 0));
  const PartMarksSummary summary = replayPartMarks(
      session, nlohmann::json::parse(R"({"objects": {"a": [{"point": 1, "motion": "knob"}]}})"), "marks.json");
  EXPECT_TRUE(summary.problems.empty());
  EXPECT_EQ(summary.parts, 1u);
  const auto record = recordOf(dir / "queue" / "a", 0);
  ASSERT_TRUE(record);
  EXPECT_TRUE(record->confirmed);
  EXPECT_EQ(record->part.motion, ControlMotion::Knob);
}

}  // namespace
}  // namespace sagrid::ui
