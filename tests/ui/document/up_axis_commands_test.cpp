// Turning the up axis on the document: the view mesh turns exactly, object.up follows, predicted
// points of the old axis go and reviewed ones stay, and undo puts everything back.
#include <gtest/gtest.h>

#include <memory>

#include "core/labels/labels.h"
#include "core/mesh/mesh.h"
#include "ui/document/annotation_document.h"
#include "ui/document/up_axis_commands.h"

namespace sagrid::ui {
namespace {

// A y-up file's box, 1 x 2 x 3 in file units, as imported (view frame z-up).
std::shared_ptr<const Mesh> yUpMesh() {
  auto mesh = std::make_shared<Mesh>();
  const Eigen::Vector3f file[] = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
  for (const auto& p : file) mesh->positions.push_back(fileToZUp(p, UpAxis::Y));
  mesh->triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  mesh->computeVertexNormals();
  mesh->fileUp = UpAxis::Y;
  mesh->fileUpDetected = true;
  mesh->fileUpConfidence = 0.4f;
  return mesh;
}

ObjectLabels labelsWithOnePredictedOneAccepted() {
  ObjectLabels labels;
  labels.object.id = "box";
  labels.object.category = "stove";
  labels.object.up = "y";
  labels.object.upConfidence = 0.4;
  AffordancePoint predicted;
  predicted.type = "heatsource";
  predicted.position = {0.5f, 2.0f, 1.0f};
  AffordancePoint accepted = predicted;
  accepted.status = AffordanceStatus::Accepted;
  accepted.position = {0.2f, 2.0f, 0.5f};
  labels.affordances = {predicted, accepted};
  return labels;
}

TEST(UpAxisCommands, TurnChangesMeshAndUpDropsPredictedPointsAndUndoes) {
  AnnotationDocument doc(yUpMesh(), labelsWithOnePredictedOneAccepted(), {});
  const Mesh before = doc.mesh();
  const auto meshIdentity = doc.sharedMesh().get();

  doc.execute(std::make_unique<TurnUpAxisCommand>(doc, UpAxis::NegX));
  EXPECT_EQ(doc.mesh().fileUp, UpAxis::NegX);
  EXPECT_FALSE(doc.mesh().fileUpDetected);
  EXPECT_NE(doc.sharedMesh().get(), meshIdentity);  // renderers upload the turned mesh
  EXPECT_EQ(doc.labels().object.up, "-x");
  EXPECT_FALSE(doc.labels().object.upConfidence.has_value());
  ASSERT_EQ(doc.points().size(), 1u);
  EXPECT_EQ(doc.points()[0].status, AffordanceStatus::Accepted);
  // The file's vertex (1, 0, 0) lies on the -x side up: it is now at the bottom (z = -1).
  EXPECT_EQ(doc.mesh().positions[1], Eigen::Vector3f(0, 0, -1));
  // Labels stay in the file's frame: the view maps them with the new axis.
  EXPECT_EQ(doc.toView(doc.points()[0].position), fileToZUp(doc.points()[0].position, UpAxis::NegX));

  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.mesh().fileUp, UpAxis::Y);
  EXPECT_EQ(doc.labels().object.up, "y");
  EXPECT_EQ(doc.labels().object.upConfidence, 0.4);
  ASSERT_EQ(doc.points().size(), 2u);
  EXPECT_EQ(doc.points()[0].status, AffordanceStatus::Predicted);
  for (std::size_t v = 0; v < before.positions.size(); ++v) {
    EXPECT_EQ(doc.mesh().positions[v], before.positions[v]);  // exact: 0/+-1 rotations
  }
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.labels().object.up, "-x");
}

TEST(UpAxisCommands, PredictionAfterATurnIsOneMoreUndoableStep) {
  AnnotationDocument doc(yUpMesh(), labelsWithOnePredictedOneAccepted(), {});
  doc.execute(std::make_unique<TurnUpAxisCommand>(doc, UpAxis::Z));
  AffordancePoint p;
  p.type = "heatsource";
  p.position = {0.5f, 0.5f, 3.0f};
  doc.execute(std::make_unique<ReplacePointsCommand>(std::vector<AffordancePoint>{p}, "predicted points"));
  ASSERT_EQ(doc.points().size(), 1u);
  EXPECT_EQ(doc.points()[0].position, p.position);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.points().size(), 1u);  // the accepted point the turn kept
  EXPECT_EQ(doc.points()[0].status, AffordanceStatus::Accepted);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.labels().object.up, "y");
  EXPECT_EQ(doc.points().size(), 2u);
}

}  // namespace
}  // namespace sagrid::ui
