// Same-geometry twins in the GUI session: two objects of one shape in other materials (a colour
// variant), the first curated, open the second with the first's points, category and units as
// predictions to confirm with one key, marked as carried in labels.json and in the curation log;
// an object of another shape still gets the model's prediction; a twin placed elsewhere in its
// file gets the points moved onto the same spot of its surface; a twin curated later changes
// nothing already opened; undo gives the model's prediction instead.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iomanip>
#include <thread>

#include "core/annotate/units_record.h"
#include "core/mesh/mesh_import.h"
#include "support/test_paths.h"
#include "ui/app/session.h"
#include "ui/document/point_commands.h"
#include "ui/document/twin_points.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

const Eigen::Vector3f kPredicted{-0.2f, 0.2f, 0.0f};  // where the scripted model puts its point
const Eigen::Vector3f kCurated{0.25f, -0.25f, 0.2f};  // where the curator moved it

// A plate with a block on it, in one material of `colour` (another vertex order and UVs for
// the second material, as another export of the same model writes it); `blockAt` moves the block,
// `placedAt` the whole object (the same mesh at another spot of its file), `noise` every
// coordinate by up to that much (a file that prints a few decimals after moving the model).
void writeObject(const fs::path& dir, const std::string& colour, float blockAt = 0.1f,
                 const Eigen::Vector3f& placedAt = Eigen::Vector3f::Zero(), float noise = 0.0f) {
  fs::create_directories(dir);
  std::ofstream(dir / "look.mtl") << "newmtl " << colour << "\nKd "
                                  << (colour == "white" ? "1 1 1" : "0 0 1") << "\n";
  std::ofstream obj(dir / "mesh.obj");
  obj << "mtllib look.mtl\nusemtl " << colour << "\n";
  const float x0 = blockAt, x1 = blockAt + 0.3f;
  const std::vector<Eigen::Vector3f> corners{
      {-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0},  {0.5f, 0.5f, 0},   {-0.5f, 0.5f, 0},
      {x0, -0.4f, 0.2f}, {x1, -0.4f, 0.2f}, {x1, -0.1f, 0.2f}, {x0, -0.1f, 0.2f},
      {x0, -0.4f, 0.0f}, {x1, -0.4f, 0.0f}, {x1, -0.1f, 0.0f}, {x0, -0.1f, 0.0f}};
  std::vector<std::array<int, 3>> faces{{1, 2, 3},   {1, 3, 4},  {5, 6, 7},   {5, 7, 8},
                                        {9, 10, 6},  {9, 6, 5},  {10, 11, 7}, {10, 7, 6},
                                        {11, 12, 8}, {11, 8, 7}, {12, 9, 5},  {12, 5, 8}};
  if (colour != "white") std::reverse(faces.begin(), faces.end());
  obj << std::setprecision(10);
  for (std::size_t i = 0; i < corners.size(); ++i) {
    Eigen::Vector3f c = corners[i] + placedAt;
    for (int a = 0; a < 3; ++a)
      c[a] += noise * float(int((i * 7 + std::size_t(a) * 3) % 5) - 2) / 2;
    obj << "v " << c.x() << " " << c.y() << " " << c.z() << "\n";
  }
  if (colour != "white") obj << "vt 0 0\nvt 1 0\nvt 1 1\n";
  for (const auto& f : faces) {
    if (colour == "white")
      obj << "f " << f[0] << " " << f[1] << " " << f[2] << "\n";
    else
      obj << "f " << f[0] << "/1 " << f[1] << "/2 " << f[2] << "/3\n";
  }
}

// A model that puts one heat source at kPredicted on every stove.
void predictOnePoint(Session& session) {
  session.setPredictorLookup([](const AnnotationDocument&) -> std::optional<PredictionJob> {
    return PredictionJob([](PredictionProgress& progress) {
      PredictionResult r;
      r.category = "stove";
      AffordancePoint heat;
      heat.type = "heatsource";
      heat.position = kPredicted;
      heat.source = "stove.heatsource@model";
      heat.confidence = 0.9f;
      r.points = {heat};
      r.objectConfidence = 0.8;
      progress.fraction = 1.0f;
      return r;
    });
  });
}

void awaitPrediction(Session& session) {
  for (int i = 0; i < 400 && session.worker().running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  session.pollPrediction();
}

// The queue a_white, b_blue (a_white's geometry), c_other (its block moved), a_white curated.
fs::path curatedQueue(Session& session) {
  const fs::path dir = test::freshTempDir() / "queue";
  writeObject(dir / "a_white", "white");
  writeObject(dir / "b_blue", "blue");
  writeObject(dir / "c_other", "white", 0.15f);
  session.logErrors = false;
  predictOnePoint(session);
  session.setCurationLog(dir / "curation.jsonl");
  session.openPaths({dir});
  awaitPrediction(session);
  EXPECT_EQ(session.document()->labels().object.id, "a_white");
  EXPECT_EQ(session.document()->points().size(), 1u);
  session.execute(std::make_unique<MovePointCommand>(0, kCurated, std::nullopt));
  EXPECT_TRUE(session.setUnits(0.01));
  EXPECT_EQ(session.queue().entry(0).state, QueueState::InProgress);  // edited, not finished yet
  return dir;
}

TEST(SessionTwin, AColourVariantOfACuratedObjectOpensWithItsPointsToConfirm) {
  Session session;
  const fs::path dir = curatedQueue(session);
  session.openEntry(1);
  const AnnotationDocument* doc = session.document();
  ASSERT_TRUE(doc);
  EXPECT_FALSE(session.worker().running());  // no prediction: the twin's points are the start
  ASSERT_EQ(doc->points().size(), 1u);
  EXPECT_TRUE(doc->points()[0].position.isApprox(kCurated));
  EXPECT_EQ(doc->points()[0].status, AffordanceStatus::Predicted);
  EXPECT_EQ(doc->points()[0].source, "carried:a_white");
  EXPECT_EQ(doc->labels().object.category, "stove");
  EXPECT_NEAR(doc->metersPerUnit(), 0.01, 1e-6);
  const auto units = recordedUnitGuess(doc->labels().object);
  ASSERT_TRUE(units);  // flagged until the curator confirms them
  EXPECT_NE(units->reason.find("a_white"), std::string::npos) << units->reason;
  EXPECT_EQ(pointsCarriedFrom(doc->labels()), "a_white");
  EXPECT_EQ(
      readLabels(dir / "b_blue" / "labels.json").object.extra.value("points_carried_from", ""),
      "a_white");
  EXPECT_EQ(doc->undoDescription(), "points carried from a_white (same geometry)");
  EXPECT_FALSE(doc->editedByHand());
  EXPECT_EQ(session.queue().entry(1).state, QueueState::Unreviewed);

  // One key: accepted as they are (not edited), and on to the next object.
  session.accept();
  EXPECT_EQ(session.queue().entry(1).state, QueueState::Accepted);
  const ObjectLabels saved = readLabels(dir / "b_blue" / "labels.json");
  ASSERT_EQ(saved.affordances.size(), 1u);
  EXPECT_EQ(saved.affordances[0].status, AffordanceStatus::Accepted);
  EXPECT_EQ(saved.reviewState, ReviewState::Done);

  // Another shape: the model's prediction, nothing carried.
  ASSERT_EQ(session.queue().current(), 2);
  awaitPrediction(session);
  ASSERT_EQ(session.document()->points().size(), 1u);
  EXPECT_TRUE(session.document()->points()[0].position.isApprox(kPredicted));
  EXPECT_EQ(session.document()->points()[0].source, "stove.heatsource@model");
  EXPECT_FALSE(pointsCarriedFrom(session.document()->labels()));

  // The log tells the carried open apart.
  std::vector<std::pair<std::string, std::string>> opens;
  for (const CurationEvent& e : readCurationLog(dir / "curation.jsonl"))
    if (e.action == CurationAction::Open) opens.emplace_back(e.object, e.carriedFrom);
  const std::vector<std::pair<std::string, std::string>> expected{
      {"a_white", ""}, {"b_blue", "a_white"}, {"c_other", ""}};
  EXPECT_EQ(opens, expected);
}

TEST(SessionTwin, ANoisyCopyPlacedFarElsewhereInItsFileGetsThePointsOnTheSameSpot) {
  // b is a's mesh placed 240 units away along x, 150 back along y and 0.5 up, every coordinate
  // off by up to 1e-6 units (1e-6 of this 1-unit object; a float's step there is 1.5e-5): the
  // curated point on a's block top lands on b's block top, at the same place on it.
  const Eigen::Vector3f placedAt(240.3f, -150.7f, 0.5f);
  const fs::path dir = test::freshTempDir() / "queue";
  writeObject(dir / "a_white", "white");
  writeObject(dir / "b_blue", "blue", 0.1f, placedAt, 1e-6f);
  // A copy with its block moved by 1 % of the object: the same outline, not the same geometry.
  writeObject(dir / "c_edited", "blue", 0.11f, placedAt);
  Session session;
  session.logErrors = false;
  predictOnePoint(session);
  session.openPaths({dir});
  awaitPrediction(session);
  session.execute(std::make_unique<MovePointCommand>(0, kCurated, std::nullopt));
  session.openEntry(1);
  const AnnotationDocument* doc = session.document();
  ASSERT_TRUE(doc);
  EXPECT_EQ(pointsCarriedFrom(doc->labels()), "a_white");
  ASSERT_EQ(doc->points().size(), 1u);
  const Eigen::Vector3f at = doc->points()[0].position;
  EXPECT_TRUE(at.isApprox(kCurated + placedAt, 1e-6f)) << at.transpose();
  // On b's block top (z 0.2, x 0.1..0.4, y -0.4..-0.1 before b was placed), not in the air.
  EXPECT_NEAR(at.z(), 0.2f + placedAt.z(), 1e-4f);
  EXPECT_GT(at.x(), 0.1f + placedAt.x());
  EXPECT_LT(at.x(), 0.4f + placedAt.x());
  EXPECT_GT(at.y(), -0.4f + placedAt.y());
  EXPECT_LT(at.y(), -0.1f + placedAt.y());
  const ObjectLabels saved = readLabels(dir / "b_blue" / "labels.json");
  ASSERT_EQ(saved.affordances.size(), 1u);
  EXPECT_TRUE(saved.affordances[0].position.isApprox(kCurated + placedAt, 1e-6f));
  EXPECT_EQ(saved.object.extra.value("points_carried_from", ""), "a_white");
  session.openEntry(2);
  EXPECT_FALSE(pointsCarriedFrom(session.document()->labels()));
  ASSERT_TRUE(session.queue().entry(2).geometry);
  EXPECT_TRUE(sameOutline(*session.queue().entry(0).geometry, *session.queue().entry(2).geometry));
}

TEST(SessionTwin, UndoingTheCarriedPointsGivesTheModelsPrediction) {
  Session session;
  curatedQueue(session);
  session.openEntry(1);
  ASSERT_TRUE(pointsCarriedFrom(session.document()->labels()));
  session.undo();
  EXPECT_FALSE(pointsCarriedFrom(session.document()->labels()));
  EXPECT_NE(session.document()->labels().object.category, "stove");  // as it opened: unknown
  awaitPrediction(session);
  const AnnotationDocument* doc = session.document();
  ASSERT_EQ(doc->points().size(), 1u);
  EXPECT_TRUE(doc->points()[0].position.isApprox(kPredicted));
  EXPECT_FALSE(doc->editedByHand());  // the prediction is the review's start again
  session.accept();
  EXPECT_EQ(session.queue().entry(1).state, QueueState::Accepted);
}

TEST(SessionTwin, TheTwinsUpAxisComesWithItsPoints) {
  Session session;
  curatedQueue(session);
  const UpAxis opened = session.document()->mesh().fileUp;
  const UpAxis turned = opened == UpAxis::NegY ? UpAxis::PosX : UpAxis::NegY;
  session.turnUpAxis(turned);  // the curator stands a up another way (its moved point stays)
  awaitPrediction(session);
  ASSERT_EQ(session.document()->labels().object.up, toString(turned));
  session.openEntry(1);
  const AnnotationDocument* doc = session.document();
  EXPECT_EQ(doc->mesh().fileUp, turned);
  EXPECT_EQ(doc->labels().object.up, toString(turned));
  ASSERT_EQ(doc->points().size(), 1u);
  EXPECT_TRUE(doc->points()[0].position.isApprox(kCurated));  // file coordinates: as they were
  session.undo();
  EXPECT_EQ(session.document()->mesh().fileUp, opened);
}

TEST(SessionTwin, ATwinCuratedLaterChangesNothingOpenedAndTheFolderRemembersGeometry) {
  const fs::path dir = test::freshTempDir() / "queue";
  writeObject(dir / "a_white", "white");
  writeObject(dir / "b_blue", "blue");
  writeObject(dir / "c_other", "white", 0.15f);
  {
    Session session;
    session.logErrors = false;
    predictOnePoint(session);
    session.openPaths({dir});
    awaitPrediction(session);
    session.openEntry(1);  // b before its twin is curated: the model's point
    awaitPrediction(session);
    ASSERT_EQ(session.document()->points().size(), 1u);
    EXPECT_TRUE(session.document()->points()[0].position.isApprox(kPredicted));
    session.navigate(-1);  // back to a, b left unreviewed
    awaitPrediction(session);
    session.execute(std::make_unique<MovePointCommand>(0, kCurated, std::nullopt));
    session.openEntry(2);  // the folder's position is now c
    awaitPrediction(session);
    // b, opened before a was curated, is not changed by it.
    const ObjectLabels b = readLabels(dir / "b_blue" / "labels.json");
    ASSERT_EQ(b.affordances.size(), 1u);
    EXPECT_TRUE(b.affordances[0].position.isApprox(kPredicted));
    EXPECT_FALSE(pointsCarriedFrom(b));
  }
  // The folder reopened in a new session opens c; a's geometry is known only from the folder's
  // state file, and b, still only predicted, opens anew with a's points (undo: its prediction).
  Session again;
  again.logErrors = false;
  again.autoPredict = false;
  again.openPaths({dir});
  ASSERT_EQ(again.queue().current(), 2);
  EXPECT_FALSE(pointsCarriedFrom(again.document()->labels()));  // another shape
  again.openEntry(1);
  ASSERT_EQ(again.document()->points().size(), 1u);
  EXPECT_TRUE(again.document()->points()[0].position.isApprox(kCurated));
  EXPECT_EQ(pointsCarriedFrom(again.document()->labels()), "a_white");
  again.undo();
  ASSERT_EQ(again.document()->points().size(), 1u);
  EXPECT_TRUE(again.document()->points()[0].position.isApprox(kPredicted));
}

}  // namespace
}  // namespace sagrid::ui
