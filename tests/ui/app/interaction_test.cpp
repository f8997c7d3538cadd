// Scripted interaction, headless (EGL): mouse and key events replayed through the same frame
// function the window uses, asserting on the document and on the labels.json saved on disk.
#include <gtest/gtest.h>

#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"
#include "ui/app/shortcuts.h"

namespace sagrid::ui {
namespace {

using test::ScriptedApp;

TEST(Interaction, DragPointAlongSurfaceThenUndoRedo) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  const Eigen::Vector3f start(-0.2f, 0.2f, 0.0f);
  const Eigen::Vector3f onBlock(0.25f, -0.25f, 0.2f);  // top of the block
  s.drag(s.pixelOf(start), s.pixelOf(onBlock));
  const AffordancePoint& moved = s.document().points()[0];
  // One drag, snapped onto the block's top face (z = 0.2), within a pixel's worth of the target.
  EXPECT_NEAR(moved.position.x(), 0.25f, 0.01f);
  EXPECT_NEAR(moved.position.y(), -0.25f, 0.01f);
  EXPECT_NEAR(moved.position.z(), 0.2f, 1e-4f);
  EXPECT_EQ(moved.status, AffordanceStatus::Edited);
  EXPECT_EQ(s.document().historySize(), 1u);  // the whole drag is one undo step
  ObjectLabels saved = readLabels(dir / "labels.json");
  EXPECT_NEAR(saved.affordances[0].position.z(), 0.2f, 1e-4f);

  s.key(GLFW_KEY_Z, GLFW_MOD_CONTROL);
  EXPECT_TRUE(s.document().points()[0].position.isApprox(start));
  saved = readLabels(dir / "labels.json");
  EXPECT_NEAR(saved.affordances[0].position.x(), -0.2f, 1e-6f);
  EXPECT_EQ(saved.affordances[0].status, AffordanceStatus::Predicted);

  s.key(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT);
  EXPECT_NEAR(s.document().points()[0].position.z(), 0.2f, 1e-4f);
  s.key(GLFW_KEY_Z, GLFW_MOD_CONTROL);
  s.key(GLFW_KEY_Y, GLFW_MOD_CONTROL);
  EXPECT_NEAR(readLabels(dir / "labels.json").affordances[0].position.z(), 0.2f, 1e-4f);
}

TEST(Interaction, ClickSelectsAcceptWithAAndDeleteWithDel) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  s.click(s.pixelOf({-0.3f, -0.3f, 0.0f}));
  ASSERT_EQ(s.document().selected(), 1);
  s.key(GLFW_KEY_A);
  EXPECT_EQ(s.document().points()[1].status, AffordanceStatus::Accepted);
  EXPECT_EQ(readLabels(dir / "labels.json").affordances[1].status, AffordanceStatus::Accepted);
  s.key(GLFW_KEY_DELETE);
  ASSERT_EQ(s.document().points().size(), 1u);
  EXPECT_EQ(s.document().points()[0].type, "heatsource");
  EXPECT_EQ(readLabels(dir / "labels.json").affordances.size(), 1u);
  // Clicking empty space deselects.
  s.click(s.pixelOf({0.0f, 0.45f, 0.0f}));
  EXPECT_EQ(s.document().selected(), -1);
}

// The part brush: with a toggle button selected and the brush on, a click on the surface gives it
// the connected surface within the radius as its part (the curator's, "marked"), Ctrl+click takes
// the brushed surface away; each one undoable step, saved at once; the selection stays.
TEST(Interaction, TheBrushMarksTheSelectedControlsPartAndCtrlTakesItAway) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  s.click(s.pixelOf({-0.3f, -0.3f, 0.0f}));
  ASSERT_EQ(s.document().selected(), 1);
  Session& session = s.app->session();
  session.partBrush.armed = true;
  session.partBrush.radiusCm = 100;  // the whole block, and never the plate it stands on
  const Eigen::Vector3f onBlock(0.25f, -0.25f, 0.2f);
  s.click(s.pixelOf(onBlock));
  EXPECT_EQ(s.document().selected(), 1);
  auto partOf = [&](const ObjectLabels& labels) {
    const nlohmann::json& extra = labels.affordances[1].extra;
    return extra.contains("control") ? extra["control"].value("part", nlohmann::json())
                                     : nlohmann::json();
  };
  nlohmann::json part = partOf(readLabels(dir / "labels.json"));
  ASSERT_FALSE(part.is_null());
  EXPECT_EQ(part.at("origin"), "marked");
  EXPECT_EQ(readLabels(dir / "labels.json").affordances[1].extra["control"]["confirmed"], true);
  // The block's 10 triangles (2 on top, 8 on the sides) are triangles 2..11, the plate's 0 and 1.
  EXPECT_EQ(part.at("triangles"), nlohmann::json::parse("[[2, 10]]"));
  // A click on the selected point's own marker brushes the surface under it (the plate here, not
  // connected to the block: added as a part of its own), and does not move the point.
  const Eigen::Vector3f before = s.document().points()[1].position;
  session.partBrush.radiusCm = 1;
  s.click(s.pixelOf({-0.3f, -0.3f, 0.0f}));
  EXPECT_EQ(s.document().selected(), 1);
  EXPECT_TRUE(s.document().points()[1].position.isApprox(before));
  nlohmann::json withPlate = partOf(readLabels(dir / "labels.json"));
  std::size_t count = 0;
  for (const auto& run : withPlate.at("triangles")) count += run[1].get<std::size_t>();
  EXPECT_EQ(count, 11u);  // the block's 10 and the plate triangle under the marker
  s.key(GLFW_KEY_Z, GLFW_MOD_CONTROL);
  // A small brush with Ctrl takes the clicked triangle away: 9 left.
  session.partBrush.radiusCm = 2;
  s.click(s.pixelOf(onBlock), GLFW_MOD_CONTROL);
  part = partOf(readLabels(dir / "labels.json"));
  std::size_t triangles = 0;
  for (const auto& run : part.at("triangles")) triangles += run[1].get<std::size_t>();
  EXPECT_EQ(triangles, 9u);
  s.key(GLFW_KEY_Z, GLFW_MOD_CONTROL);
  EXPECT_EQ(partOf(readLabels(dir / "labels.json")).at("triangles"), nlohmann::json::parse("[[2, 10]]"));
  s.key(GLFW_KEY_Z, GLFW_MOD_CONTROL);
  EXPECT_TRUE(partOf(readLabels(dir / "labels.json")).is_null());
}

// F with a point selected: a close-up centred on it, same viewing direction; F again (or with
// nothing selected): the whole object.
TEST(Interaction, FFramesTheSelectedPointThenTheObject) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  Camera& camera = s.app->session().camera();
  const float yaw = camera.yaw(), pitch = camera.pitch();
  s.click(s.pixelOf({-0.3f, -0.3f, 0.0f}));
  ASSERT_EQ(s.document().selected(), 1);
  s.key(GLFW_KEY_F);
  EXPECT_TRUE(camera.target().isApprox(Eigen::Vector3f(-0.3f, -0.3f, 0.0f), 1e-4f));
  const float closeUp = camera.distance();
  EXPECT_FLOAT_EQ(camera.yaw(), yaw);
  EXPECT_FLOAT_EQ(camera.pitch(), pitch);
  // The selected point is now in the middle of the viewport.
  const Eigen::Vector2f centre = s.pixelOf({-0.3f, -0.3f, 0.0f});
  const ViewportRect& viewport = s.app->session().viewport();
  EXPECT_NEAR(centre.x(), viewport.x + 0.5f * viewport.width, 1.0f);
  EXPECT_NEAR(centre.y(), viewport.y + 0.5f * viewport.height, 1.0f);
  s.key(GLFW_KEY_F);  // again: the whole object
  const float whole = camera.distance();
  EXPECT_LT(closeUp, 0.2f * whole);
  EXPECT_TRUE(camera.target().isApprox(Eigen::Vector3f(0, 0, 0.1f), 1e-4f));
  s.key(GLFW_KEY_F);  // and the close-up again
  EXPECT_FLOAT_EQ(camera.distance(), closeUp);
  s.key(GLFW_KEY_ESCAPE);  // nothing selected: the whole object
  s.key(GLFW_KEY_F);
  EXPECT_FLOAT_EQ(camera.distance(), whole);
}

TEST(Interaction, ShiftClickAddsPointOfCurrentTypeOnSurface) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  s.key(GLFW_KEY_3);  // fluidsource: on a stove the stove's own types come first
  EXPECT_EQ(s.app->session().currentType(), "fluidsource");
  s.click(s.pixelOf({0.3f, -0.2f, 0.2f}), GLFW_MOD_SHIFT);
  ASSERT_EQ(s.document().points().size(), 3u);
  const AffordancePoint& added = s.document().points()[2];
  EXPECT_EQ(added.type, "fluidsource");
  EXPECT_EQ(added.status, AffordanceStatus::Added);
  EXPECT_NEAR(added.position.z(), 0.2f, 1e-4f);
  ASSERT_TRUE(added.normal.has_value());
  EXPECT_NEAR(added.normal->z(), 1.0f, 1e-4f);
  const ObjectLabels saved = readLabels(dir / "labels.json");
  ASSERT_EQ(saved.affordances.size(), 3u);
  EXPECT_EQ(saved.affordances[2].source, "human");
  s.key(GLFW_KEY_Z, GLFW_MOD_CONTROL);
  EXPECT_EQ(readLabels(dir / "labels.json").affordances.size(), 2u);
}

TEST(Interaction, NewPointTypeFollowsTheObjectsCategory) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  EXPECT_EQ(s.app->session().currentType(), "heatsource");
  s.key(GLFW_KEY_3);  // fluidsource, which a stove does not have
  s.app->session().openObject(dir / "mesh.obj", dir / "labels.json");
  EXPECT_EQ(s.app->session().currentType(), "heatsource");
  // A sink: heatsource becomes its first type; togglebutton, which it has, is kept.
  ObjectLabels sink = readLabels(dir / "labels.json");
  sink.object.category = "sink";
  std::filesystem::create_directories(dir / "sink");
  writeLabels(dir / "sink" / "labels.json", sink);
  std::filesystem::copy_file(dir / "mesh.obj", dir / "sink" / "mesh.obj");
  s.app->session().openObject(dir / "sink" / "mesh.obj", dir / "sink" / "labels.json");
  EXPECT_EQ(s.app->session().currentType(), "fluidsource");
  s.key(GLFW_KEY_2);  // togglebutton
  s.app->session().openObject(dir / "sink" / "mesh.obj", dir / "sink" / "labels.json");
  EXPECT_EQ(s.app->session().currentType(), "togglebutton");
}

TEST(Interaction, NumberKeysChooseTheCategorysOwnTypesFirst) {
  // A curator pressed 2 for a knob on a stove and got a fluid source: 2 is the knob on a stove
  // and on a sink, 1 the category's first type, the other types after them.
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  EXPECT_EQ(s.app->session().typesForKeys(),
            (std::vector<std::string>{"heatsource", "togglebutton", "fluidsource", "particleremover",
                                      "particleapplier"}));
  s.key(GLFW_KEY_2);
  EXPECT_EQ(s.app->session().currentType(), "togglebutton");
  s.key(GLFW_KEY_1);
  EXPECT_EQ(s.app->session().currentType(), "heatsource");
  ObjectLabels sink = readLabels(dir / "labels.json");
  sink.object.category = "sink";
  sink.affordances.clear();
  std::filesystem::create_directories(dir / "sink");
  writeLabels(dir / "sink" / "labels.json", sink);
  std::filesystem::copy_file(dir / "mesh.obj", dir / "sink" / "mesh.obj");
  s.app->session().openObject(dir / "sink" / "mesh.obj", dir / "sink" / "labels.json");
  s.key(GLFW_KEY_1);
  EXPECT_EQ(s.app->session().currentType(), "fluidsource");
  s.key(GLFW_KEY_2);
  EXPECT_EQ(s.app->session().currentType(), "togglebutton");
  s.key(GLFW_KEY_9);  // no ninth type: nothing changes
  EXPECT_EQ(s.app->session().currentType(), "togglebutton");
}

TEST(Interaction, NewPointTypeFollowsTheCategoryThePredictionGives) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  EXPECT_EQ(s.app->session().currentType(), "heatsource");  // the stove's
  // A new object: no category until the prediction says sink.
  std::filesystem::create_directories(dir / "new");
  std::filesystem::copy_file(dir / "mesh.obj", dir / "new" / "mesh.obj");
  s.app->session().openObject(dir / "new" / "mesh.obj", dir / "new" / "labels.json");
  PredictionResult sink;
  sink.category = "sink";
  s.predict(sink);
  EXPECT_EQ(s.document().labels().object.category, "sink");
  EXPECT_EQ(s.app->session().currentType(), "fluidsource");
}

TEST(Interaction, AOnAPointTheCuratorPlacedGoesOnToTheNextObject) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  s.click(s.pixelOf({0.0f, 0.0f, 0.0f}), GLFW_MOD_SHIFT);  // added: selected, "added"
  ASSERT_EQ(s.document().points().size(), 3u);
  ASSERT_EQ(s.document().selected(), 2);
  s.key(GLFW_KEY_A);  // nothing to accept on it: accept all, as with none selected
  const ObjectLabels saved = readLabels(dir / "labels.json");
  EXPECT_EQ(saved.reviewState, ReviewState::Done);
  EXPECT_EQ(saved.affordances[2].status, AffordanceStatus::Added);  // not turned into "accepted"
  EXPECT_EQ(saved.affordances[0].status, AffordanceStatus::Accepted);
}

TEST(Interaction, AnEditedObjectCountsAsReviewedWhenTheCuratorPressesA) {
  // Both curators read "k / n reviewed" rising at the first drag as "done": an edit makes the
  // object "in progress", A finishes it as edited.
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  s.drag(s.pixelOf({-0.2f, 0.2f, 0.0f}), s.pixelOf({0.25f, -0.25f, 0.2f}));
  EXPECT_EQ(s.app->session().queue().entry(0).state, QueueState::InProgress);
  EXPECT_EQ(s.app->session().queue().reviewedCount(), 0u);
  s.key(GLFW_KEY_A);
  EXPECT_EQ(s.app->session().queue().entry(0).state, QueueState::Edited);
  EXPECT_EQ(s.app->session().queue().reviewedCount(), 1u);
}

TEST(Interaction, AWithNothingSelectedAcceptsAllAndMarksObjectReviewed) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  s.key(GLFW_KEY_A);  // one keypress for an object whose predictions are right
  const ObjectLabels saved = readLabels(dir / "labels.json");
  EXPECT_EQ(saved.reviewState, ReviewState::Done);
  for (const auto& p : saved.affordances) EXPECT_EQ(p.status, AffordanceStatus::Accepted);
  EXPECT_EQ(s.app->session().queue().entry(0).state, QueueState::Accepted);
}

TEST(Interaction, CtrlSSavesAndOrbitDoesNotEdit) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  const float yaw = s.app->session().camera().yaw();
  s.drag(s.pixelOf({0.0f, 0.4f, 0.0f}), s.pixelOf({0.3f, 0.4f, 0.0f}));  // empty space: orbit
  EXPECT_NE(s.app->session().camera().yaw(), yaw);
  EXPECT_EQ(s.document().historySize(), 0u);
  std::filesystem::remove(dir / "labels.json");
  s.key(GLFW_KEY_S, GLFW_MOD_CONTROL);
  ASSERT_TRUE(std::filesystem::exists(dir / "labels.json"));
  EXPECT_EQ(readLabels(dir / "labels.json").affordances.size(), 2u);
}

TEST(Interaction, DroppedBrokenFileShowsErrorAndQueueGoesOn) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  std::ofstream(dir / "broken.obj") << "this is not an obj\n";
  s.frame({InputEvent::drop({(dir / "broken.obj").string()})});
  EXPECT_FALSE(s.app->session().pendingErrors().empty());
  EXPECT_EQ(s.app->session().queue().size(), 2u);
  s.key(GLFW_KEY_P);  // back to the good object
  ASSERT_NE(s.app->session().document(), nullptr);
  EXPECT_EQ(s.document().points().size(), 2u);
}

TEST(Interaction, F12KeepsTheScreenshotsOfAnEarlierSession) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  std::ofstream(dir / "sagrid-screenshot-1.png") << "an earlier session's";
  s.key(GLFW_KEY_F12);
  s.frame({});
  std::ifstream earlier(dir / "sagrid-screenshot-1.png");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(earlier), {}), "an earlier session's");
  EXPECT_TRUE(std::filesystem::exists(dir / "sagrid-screenshot-2.png"));
}

TEST(Interaction, TheWheelZoomsTowardsTheSurfaceUnderThePointer) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  const Eigen::Vector3f spot(0.3f, 0.3f, 0.0f);  // on the plate, away from the view's middle
  const Eigen::Vector2f pixel = s.pixelOf(spot);
  const float distance = s.app->session().camera().distance();
  s.moveTo(pixel);
  s.frame({InputEvent::scroll(0.0f, 3.0f)});
  EXPECT_LT(s.app->session().camera().distance(), 0.7f * distance);
  EXPECT_LT((s.pixelOf(spot) - pixel).norm(), 1.0f);  // the spot stays under the pointer
  // Off the object the wheel zooms about the view's middle.
  const Eigen::Vector3f target = s.app->session().camera().target();
  s.moveTo({2.0f, 2.0f});
  s.frame({InputEvent::scroll(0.0f, -3.0f)});
  EXPECT_LT((s.app->session().camera().target() - target).norm(), 1e-6f);
}

TEST(Interaction, SwitchingToNoneDropsTheOldCategorysFieldsWithItsPoints) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  DistanceField heat;
  heat.type = "heatsource";
  heat.voxels = {VoxelIndex{1, 2, 3}};
  heat.distances = {0.1f};
  s.app->session().document()->setPredictedFields({heat});
  ASSERT_FALSE(s.document().predictedFields().empty());
  s.app->session().switchCategory("none");
  EXPECT_TRUE(s.document().points().empty());
  EXPECT_TRUE(s.document().predictedFields().empty());
}

TEST(Interaction, KeypadKeysShowTheWholeObjectFromAboveTheFrontAndTheRight) {
  const auto dir = sagrid::test::freshTempDir();
  ScriptedApp s(dir);
  s.key(GLFW_KEY_KP_7);
  EXPECT_GT(s.app->session().camera().pitch(), 1.5f);  // straight down, all but
  s.key(GLFW_KEY_KP_1);
  EXPECT_NEAR(s.app->session().camera().pitch(), 0.0f, 1e-6f);
  EXPECT_NEAR(s.app->session().camera().yaw(), -1.5707963f, 1e-6f);
  EXPECT_LT(s.app->session().camera().eye().y(), -0.5f);  // in front of the object (-y)
  s.key(GLFW_KEY_KP_3);
  EXPECT_GT(s.app->session().camera().eye().x(), 0.5f);
  // Each shows the whole object: the plate's corners are on screen.
  Eigen::Vector2f pixel;
  s.key(GLFW_KEY_KP_7);
  for (const Eigen::Vector3f& corner : {Eigen::Vector3f(-0.5f, -0.5f, 0), Eigen::Vector3f(0.5f, 0.5f, 0)}) {
    ASSERT_TRUE(s.app->session().camera().project(corner, pixel));
    EXPECT_GE(pixel.x(), 0.0f);
    EXPECT_LE(pixel.x(), float(s.app->session().camera().width()));
  }
}

TEST(Interaction, HelpOverlayListsEveryShortcutKey) {
  // The overlay is generated from the same table the handler documents; spot-check key entries.
  bool undo = false, accept = false;
  for (const auto& s : shortcutHelp()) {
    undo |= std::string(s.keys) == "Ctrl+Z";
    accept |= std::string(s.keys) == "A";
  }
  EXPECT_TRUE(undo);
  EXPECT_TRUE(accept);
}

}  // namespace
}  // namespace sagrid::ui
