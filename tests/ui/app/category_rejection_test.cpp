// An object the category classifier rejects opens with category "none" and no points, and the
// curator can then pick its category (the prediction is replayed through a scripted job, the
// session and worker are the real ones).
#include <gtest/gtest.h>

#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"

namespace sagrid::ui {
namespace {

using test::ScriptedApp;

// What annotateMeshFile returns for an object rejected with `closest` its likeliest category.
PredictionResult rejectedAs(const std::string& closest) {
  PredictionResult r;
  r.category = "none";
  r.rejected = true;
  r.closestCategory = closest;
  return r;
}

// A scripted window with the scene's own object open.
struct OpenScene {
  std::filesystem::path dir = sagrid::test::freshTempDir();
  ScriptedApp scripted{dir};
  OpenScene() { session().openObject(dir / "mesh.obj", dir / "labels.json"); }
  Session& session() { return scripted.app->session(); }
};

TEST(CategoryRejection, RejectedObjectOpensWithNoPointsAndCuratorPicksCategory) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  // The object as `annotate` would leave it before a category is known: no category, no points.
  ObjectLabels fresh = readLabels(dir / "labels.json");
  fresh.object.category.clear();
  fresh.affordances.clear();
  std::filesystem::create_directories(dir / "fresh");
  writeLabels(dir / "fresh" / "labels.json", fresh);
  std::filesystem::copy_file(dir / "mesh.obj", dir / "fresh" / "mesh.obj");
  auto& session = s.app->session();
  session.openObject(dir / "fresh" / "mesh.obj", dir / "fresh" / "labels.json");
  s.predict(rejectedAs("stove"));
  EXPECT_EQ(s.document().labels().object.category, "none");
  EXPECT_TRUE(s.document().points().empty());
  EXPECT_EQ(readLabels(dir / "fresh" / "labels.json").object.category, "none");
  EXPECT_EQ(session.predictionNote(), "not a known category (closest: stove): no points");
  // The curator picks the category (the object panel's combo calls setCategory).
  session.document()->setCategory("stove");
  EXPECT_EQ(readLabels(dir / "fresh" / "labels.json").object.category, "stove");
}

// The note names the words of the file's name that moved the decision; where the name changed the
// category, it also says what the shape alone decided: for a rejected object and for one filed by
// its name.
TEST(CategoryRejection, TheNoteNamesTheWordsOfTheFileNameThatMovedTheDecision) {
  OpenScene open;
  PredictionResult r = rejectedAs("sink");
  r.categoryNameWords = {"coffee", "machine"};
  open.scripted.predict(r);
  EXPECT_EQ(open.session().predictionNote(),
            "not a known category (closest: sink): no points (read from its file's name too: "
            "coffee, machine)");
  r.categoryNameWords = {"oven"};  // the next prediction: the shape alone filed it as a sink
  r.categoryByShapeAlone = "sink";
  open.scripted.predict(r);
  EXPECT_EQ(open.session().predictionNote(),
            "not a known category (closest: sink): no points (read from its file's name too: "
            "oven; by its shape alone: a sink)");
  PredictionResult stove;  // the next prediction, filed by its name
  stove.category = "stove";
  stove.categoryNameWords = {"kitchen", "stove"};
  stove.categoryByShapeAlone = "none";
  open.scripted.predict(stove);
  EXPECT_EQ(open.session().predictionNote(),
            "filed as a stove by its file's name (kitchen, stove; by its shape alone: not a known "
            "category)");
}

TEST(CategoryRejection, TheObjectPanelSaysWhyTheEvidenceGateRejected) {
  OpenScene open;
  PredictionResult r = rejectedAs("sink");
  r.rejectedByEvidence = true;
  open.scripted.predict(r);
  auto& session = open.session();
  EXPECT_EQ(session.predictionNote(),
            "shaped like a sink, but the sink models find none of its parts on it: no points");
  // The next prediction (or object) starts without it.
  session.setPredictorLookup(
      [](const AnnotationDocument&) { return std::optional<PredictionJob>{}; });
  session.runPrediction();
  EXPECT_TRUE(session.predictionNote().empty());
}

}  // namespace
}  // namespace sagrid::ui
