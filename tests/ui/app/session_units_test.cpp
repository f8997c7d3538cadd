// The curator's units in the GUI session (issue 41): any scale typed in, one undoable step, a
// bad one refused with an error; units set on one object of a source carried, as a guess that
// says so, to the objects of that source whose units are only guessed, and to no other.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "core/annotate/units_record.h"
#include "support/test_paths.h"
#include "ui/app/session.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// A stove 1.3 units wide whose units annotate guessed as metres, from repository `repo`.
void writeObject(const fs::path& dir, const std::string& repo) {
  fs::create_directories(dir);
  std::ofstream(dir / "mesh.obj") << "v 0 0 0\nv 1.3 0 0\nv 1.3 1 0\nv 0 1 0\nv 0 0 1.3\nf 1 2 3\nf 1 3 4\nf 1 2 5\n";
  std::ofstream(dir / "provenance.json") << R"({"repo": ")" << repo << R"("})";
  ObjectLabels labels;
  labels.object.id = dir.filename().string();
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  labels.object.up = "z";
  UnitGuess guess;
  guess.unit = "m";
  guess.reason = "largest extent 1.3 units";
  recordUnitGuess(labels.object, guess);
  writeLabels(dir / "labels.json", labels);
}

TEST(SessionUnits, TypedUnitsAreOneStepAndCarryToTheirSourcesGuessedObjects) {
  const fs::path dir = test::freshTempDir() / "queue";
  writeObject(dir / "a_kit", "someone/kit");
  writeObject(dir / "b_kit", "someone/kit");
  writeObject(dir / "c_other", "someone/else");
  Session session;
  session.autoPredict = false;
  session.logErrors = false;
  session.openPaths({dir});
  ASSERT_TRUE(session.document());
  EXPECT_FLOAT_EQ(session.document()->metersPerUnit(), 1.0f);

  // Bad values: an error each, nothing changed.
  const std::size_t steps = session.document()->historySize();
  for (double bad : {0.0, -0.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_FALSE(session.setUnits(bad)) << bad;
  EXPECT_EQ(session.pendingErrors().size(), 4u);
  EXPECT_EQ(session.document()->historySize(), steps);

  // A kit's scale: one undoable step, the curator's (no guess left).
  ASSERT_TRUE(session.setUnits(0.69));
  EXPECT_EQ(session.document()->historySize(), steps + 1);
  EXPECT_NEAR(session.document()->metersPerUnit(), 0.69, 1e-6);
  EXPECT_FALSE(recordedUnitGuess(session.document()->labels().object));

  // The kit's next object opens with it, flagged as a guess naming where it comes from.
  session.openEntry(1);
  ASSERT_TRUE(session.document());
  EXPECT_NEAR(session.document()->metersPerUnit(), 0.69, 1e-6);
  const auto carried = recordedUnitGuess(session.document()->labels().object);
  ASSERT_TRUE(carried);
  EXPECT_NE(carried->reason.find("someone/kit"), std::string::npos) << carried->reason;
  session.saveNow();
  EXPECT_NEAR(readLabels(dir / "b_kit" / "labels.json").object.extra.value("meters_per_unit", 1.0), 0.69, 1e-9);

  // Another source keeps its own guess.
  session.openEntry(2);
  ASSERT_TRUE(session.document());
  EXPECT_FLOAT_EQ(session.document()->metersPerUnit(), 1.0f);

  // Units the curator set on an object are never replaced by a carried guess.
  ASSERT_TRUE(session.setUnits(0.01));
  session.openEntry(1);
  ASSERT_TRUE(session.setUnits(0.5));
  session.openEntry(0);
  EXPECT_NEAR(session.document()->metersPerUnit(), 0.69, 1e-6);
}

}  // namespace
}  // namespace sagrid::ui
