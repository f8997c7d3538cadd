// Commands on the annotation document: do/undo/redo restore exact values, autosave writes
// labels.json after every change, and the hand-edit bookkeeping the review queue relies on.
#include <gtest/gtest.h>

#include <memory>

#include "core/labels/labels.h"
#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"
#include "ui/document/annotation_document.h"
#include "ui/document/point_commands.h"

namespace sagrid::ui {
namespace {

std::shared_ptr<const Mesh> plate() {
  return std::make_shared<Mesh>(test::quadZ({-0.5f, -0.5f}, {0.5f, 0.5f}, 0.0f));
}

ObjectLabels twoPoints() {
  ObjectLabels labels;
  labels.object.id = "plate";
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  AffordancePoint heat;
  heat.type = "heatsource";
  heat.position = {0.1f, 0.2f, 0.0f};
  heat.confidence = 0.8f;
  AffordancePoint toggle;
  toggle.type = "togglebutton";
  toggle.position = {-0.3f, 0.0f, 0.0f};
  labels.affordances = {heat, toggle};
  return labels;
}

TEST(DocumentCommands, MoveUndoRedoRestoresPositionAndStatus) {
  AnnotationDocument doc(plate(), twoPoints(), {});
  doc.execute(
      std::make_unique<MovePointCommand>(0, Eigen::Vector3f(0.4f, -0.1f, 0.0f), std::nullopt));
  EXPECT_TRUE(doc.points()[0].position.isApprox(Eigen::Vector3f(0.4f, -0.1f, 0.0f)));
  EXPECT_EQ(doc.points()[0].status, AffordanceStatus::Edited);
  EXPECT_EQ(doc.points()[0].source, "human");
  EXPECT_TRUE(doc.editedByHand());
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.points()[0].position.isApprox(Eigen::Vector3f(0.1f, 0.2f, 0.0f)));
  EXPECT_EQ(doc.points()[0].status, AffordanceStatus::Predicted);
  EXPECT_FALSE(doc.editedByHand());
  ASSERT_TRUE(doc.redo());
  EXPECT_TRUE(doc.points()[0].position.isApprox(Eigen::Vector3f(0.4f, -0.1f, 0.0f)));
  EXPECT_FALSE(doc.redo());
}

TEST(DocumentCommands, AddDeleteUndoKeepOrder) {
  AnnotationDocument doc(plate(), twoPoints(), {});
  AffordancePoint added;
  added.type = "fluidsource";
  added.position = {0.0f, 0.4f, 0.0f};
  doc.execute(std::make_unique<AddPointCommand>(added));
  ASSERT_EQ(doc.points().size(), 3u);
  EXPECT_EQ(doc.points()[2].status, AffordanceStatus::Added);
  EXPECT_EQ(doc.selected(), 2);
  doc.execute(std::make_unique<DeletePointCommand>(0));
  ASSERT_EQ(doc.points().size(), 2u);
  EXPECT_EQ(doc.points()[0].type, "togglebutton");
  EXPECT_EQ(doc.selected(), -1);
  doc.undo();
  ASSERT_EQ(doc.points().size(), 3u);
  EXPECT_EQ(doc.points()[0].type, "heatsource");
  EXPECT_EQ(doc.points()[0].confidence.value_or(0), 0.8f);
  doc.undo();
  EXPECT_EQ(doc.points().size(), 2u);
}

TEST(DocumentCommands, AcceptAllIsOneUndoStep) {
  AnnotationDocument doc(plate(), twoPoints(), {});
  doc.execute(makeAcceptAllCommand(doc.labels()));
  EXPECT_TRUE(doc.allAccepted());
  EXPECT_FALSE(doc.editedByHand());
  EXPECT_EQ(doc.historySize(), 1u);
  doc.undo();
  EXPECT_EQ(doc.points()[0].status, AffordanceStatus::Predicted);
  EXPECT_EQ(doc.points()[1].status, AffordanceStatus::Predicted);
}

TEST(DocumentCommands, ChangeTypeAndSetCoordinates) {
  AnnotationDocument doc(plate(), twoPoints(), {});
  doc.execute(std::make_unique<ChangeTypeCommand>(1, "fluidsource"));
  EXPECT_EQ(doc.points()[1].type, "fluidsource");
  doc.execute(makeSetCoordinatesCommand(1, {0.25f, 0.25f, 0.0f}));
  EXPECT_EQ(doc.undoDescription(), "Set coordinates");
  doc.undo();
  doc.undo();
  EXPECT_EQ(doc.points()[1].type, "togglebutton");
  EXPECT_TRUE(doc.points()[1].position.isApprox(Eigen::Vector3f(-0.3f, 0.0f, 0.0f)));
}

TEST(DocumentCommands, EveryChangeIsAutosaved) {
  const auto dir = test::freshTempDir();
  const auto path = dir / "labels.json";
  AnnotationDocument doc(plate(), twoPoints(), path);
  doc.execute(
      std::make_unique<MovePointCommand>(1, Eigen::Vector3f(0.3f, 0.3f, 0.0f), std::nullopt));
  ObjectLabels saved = readLabels(path);
  ASSERT_EQ(saved.affordances.size(), 2u);
  EXPECT_NEAR(saved.affordances[1].position.x(), 0.3f, 1e-6f);
  EXPECT_EQ(saved.affordances[1].status, AffordanceStatus::Edited);
  doc.undo();
  saved = readLabels(path);
  EXPECT_NEAR(saved.affordances[1].position.x(), -0.3f, 1e-6f);
  EXPECT_EQ(saved.affordances[1].status, AffordanceStatus::Predicted);
}

TEST(DocumentCommands, NewEditDropsRedoBranch) {
  AnnotationDocument doc(plate(), twoPoints(), {});
  doc.execute(std::make_unique<AcceptPointCommand>(0));
  doc.undo();
  EXPECT_TRUE(doc.canRedo());
  doc.execute(std::make_unique<DeletePointCommand>(1));
  EXPECT_FALSE(doc.canRedo());
  EXPECT_EQ(doc.points()[0].status, AffordanceStatus::Predicted);
}

TEST(DocumentCommands, YUpFilesMapBetweenFrames) {
  auto mesh = std::make_shared<Mesh>(*plate());
  mesh->fileUp = UpAxis::Y;
  AnnotationDocument doc(mesh, twoPoints(), {});
  const Eigen::Vector3f file(0.1f, 0.2f, 0.3f);
  EXPECT_TRUE(doc.toView(file).isApprox(Eigen::Vector3f(0.1f, -0.3f, 0.2f)));
  EXPECT_TRUE(doc.toFile(doc.toView(file)).isApprox(file));
}

TEST(DocumentCommands, LabelFieldsMeasureDistanceToNearestPointOfEachType) {
  AnnotationDocument doc(plate(), twoPoints(), {});
  const auto fields = doc.labelFields();
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[0].type, "heatsource");
  ASSERT_FALSE(fields[0].voxels.empty());
  const Eigen::Vector3f heat(0.1f, 0.2f, 0.0f);
  for (std::size_t i = 0; i < fields[0].voxels.size(); i += 97) {
    EXPECT_NEAR(fields[0].distances[i], (fields[0].center(i) - heat).norm(), 1e-5f);
  }
}

}  // namespace
}  // namespace sagrid::ui
