// The curator's mass on the document: setting it writes labels object.mass_kg (what the exports
// read), undo restores the previous value or its absence, "Estimate" clears it; the estimate
// shown beside it is the physics estimate of the document's mesh, cached until the mesh changes.
#include "ui/document/mass_commands.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/common/atomic_file.h"
#include "core/labels/labels.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"
#include "ui/document/annotation_document.h"
#include "ui/document/mass_estimate.h"

namespace sagrid::ui {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<const Mesh> boxMesh() {
  return std::make_shared<Mesh>(test::box({0, 0, 0}, {1.0f, 0.5f, 0.2f}));
}

ObjectLabels stoveLabels() {
  ObjectLabels labels;
  labels.object.id = "box";
  labels.object.category = "stove";
  labels.object.extra["units"] = "m";
  return labels;
}

TEST(MassCommands, SetUndoRedoAndClearReachTheSavedLabels) {
  const auto dir = test::freshTempDir();
  AnnotationDocument doc(boxMesh(), stoveLabels(), dir / "labels.json");
  EXPECT_FALSE(curatedMass(doc.labels()));
  doc.execute(std::make_unique<SetMassCommand>(12.5));
  EXPECT_EQ(curatedMass(doc.labels()), 12.5);
  EXPECT_DOUBLE_EQ(readLabels(dir / "labels.json").object.extra.at("mass_kg").get<double>(), 12.5);
  doc.execute(std::make_unique<SetMassCommand>(20.0));
  doc.undo();
  EXPECT_EQ(curatedMass(doc.labels()), 12.5);
  doc.undo();
  EXPECT_FALSE(curatedMass(doc.labels()));
  EXPECT_FALSE(doc.labels().object.extra.contains("mass_kg"));
  doc.redo();
  EXPECT_EQ(curatedMass(doc.labels()), 12.5);
  doc.execute(std::make_unique<SetMassCommand>(std::nullopt));  // "Estimate"
  EXPECT_FALSE(readLabels(dir / "labels.json").object.extra.contains("mass_kg"));
}

TEST(MassEstimate, EstimatesTheDocumentsMeshOnceUntilItChanges) {
  AnnotationDocument doc(boxMesh(), stoveLabels(), {});
  MassEstimate estimate;
  const physics::MassProperties* first = estimate.forDocument(doc);
  ASSERT_NE(first, nullptr) << estimate.error();
  // A 1 x 0.5 x 0.2 m solid box: 0.1 m^3 at the stove's bulk density.
  EXPECT_NEAR(first->volume, 0.1, 0.01);
  EXPECT_NEAR(first->mass, first->volume * first->density, 1e-9);
  EXPECT_EQ(estimate.forDocument(doc), first);  // cached: the same object, not recomputed
  doc.setCategory("sink");
  const physics::MassProperties* sink = estimate.forDocument(doc);
  ASSERT_NE(sink, nullptr);
  EXPECT_DOUBLE_EQ(sink->density, physics::densityFor("sink").kilogramsPerCubicMetre);
}

}  // namespace
}  // namespace sagrid::ui
