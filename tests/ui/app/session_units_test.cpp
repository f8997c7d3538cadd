// The curator's units in the GUI session (issue 41): any scale typed in, one undoable step, a
// bad one refused with an error; units set on one object of a source carried, as a guess that
// says so, to the objects of that source whose units are only guessed, and to no other.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>
#include <fstream>
#include <limits>

#include "core/annotate/units_record.h"
#include "support/test_paths.h"
#include "ui/app/session.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// A stove 1.3 units wide whose units annotate guessed as metres (`sure`: no other unit fits its
// size), from repository `repo`.
void writeObject(const fs::path& dir, const std::string& repo, bool sure = false) {
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
  guess.sure = sure;
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

TEST(SessionUnits, ASureGuessFarFromTheSourcesUnitsIsNotReplacedByThem) {
  const fs::path dir = test::freshTempDir() / "queue";
  writeObject(dir / "a_microwave", "someone/kit");
  writeObject(dir / "b_fridge", "someone/kit", /*sure=*/true);
  writeObject(dir / "c_sink", "someone/kit");
  Session session;
  session.autoPredict = false;
  session.logErrors = false;
  session.openPaths({dir});
  ASSERT_TRUE(session.setUnits(0.18));
  session.openEntry(1);  // its size fits metres alone: its own guess stands
  EXPECT_FLOAT_EQ(session.document()->metersPerUnit(), 1.0f);
  session.openEntry(2);  // its guess is one of several: the source's units
  EXPECT_NEAR(session.document()->metersPerUnit(), 0.18, 1e-6);
  // A kit's scale within 2x of a sure metres guess is the kit's: carried.
  ASSERT_TRUE(session.setUnits(0.69));
  session.openEntry(1);
  EXPECT_NEAR(session.document()->metersPerUnit(), 0.69, 1e-6);
  session.openEntry(0);
  ASSERT_TRUE(session.setUnits(0.18));

  // A new object, opened before its prediction: the source's units until the prediction's own
  // guess says only metres fit.
  fs::create_directories(dir / "d_new");
  fs::copy_file(dir / "a_microwave" / "mesh.obj", dir / "d_new" / "mesh.obj");
  fs::copy_file(dir / "a_microwave" / "provenance.json", dir / "d_new" / "provenance.json");
  session.addPaths({dir / "d_new" / "mesh.obj"});
  ASSERT_TRUE(session.document());
  EXPECT_NEAR(session.document()->metersPerUnit(), 0.18, 1e-6);
  session.setPredictorLookup([](const AnnotationDocument&) -> std::optional<PredictionJob> {
    return PredictionJob([](PredictionProgress& progress) {
      PredictionResult r;
      r.category = "stove";
      UnitGuess metres;
      metres.sure = true;
      metres.reason = "only metres fit";
      r.units = metres;
      progress.fraction = 1.0f;
      return r;
    });
  });
  session.runPrediction();
  for (int i = 0; i < 400 && session.worker().running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  session.pollPrediction();
  EXPECT_FLOAT_EQ(session.document()->metersPerUnit(), 1.0f);
}

}  // namespace
}  // namespace sagrid::ui
