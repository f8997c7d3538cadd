// The curator's units on the document: a guessed unit is flagged until set; setting one writes
// object.meters_per_unit, drops the guess, changes the sizes and masses the document reports, and
// undo brings the guess back.
#include "ui/document/units_commands.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/annotate/units_record.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"
#include "ui/document/annotation_document.h"
#include "ui/document/category_commands.h"

namespace sagrid::ui {
namespace {

TEST(UnitsCommands, AGuessIsFlaggedSettingUnitsConfirmsAndUndoRestoresTheGuess) {
  const auto dir = test::freshTempDir();
  ObjectLabels labels;
  labels.object.id = "stove";
  labels.object.category = "stove";
  AnnotationDocument doc(std::make_shared<Mesh>(test::box({0, 0, 0}, {90.0f, 60.0f, 60.0f})), labels,
                         dir / "labels.json");
  EXPECT_FALSE(doc.unitsKnown());
  doc.setUnitGuess(guessMetersPerUnit(90.0, "stove"));
  EXPECT_TRUE(doc.unitsKnown());
  EXPECT_FLOAT_EQ(doc.metersPerUnit(), 0.01f);
  ASSERT_TRUE(recordedUnitGuess(readLabels(dir / "labels.json").object));

  doc.execute(std::make_unique<SetUnitsCommand>(0.0254));  // the curator knows better: inches
  EXPECT_FLOAT_EQ(doc.metersPerUnit(), 0.0254f);
  const ObjectLabels saved = readLabels(dir / "labels.json");
  EXPECT_FALSE(recordedUnitGuess(saved.object));
  EXPECT_DOUBLE_EQ(saved.object.extra.at("meters_per_unit").get<double>(), 0.0254);

  doc.undo();
  EXPECT_FLOAT_EQ(doc.metersPerUnit(), 0.01f);
  EXPECT_TRUE(recordedUnitGuess(readLabels(dir / "labels.json").object));
}

TEST(UnitsCommands, UnitsTheSourceDeclaredAreKnownAndTheCuratorsReplaceThem) {
  const auto dir = test::freshTempDir();
  ObjectLabels labels;
  labels.object.id = "sink";
  labels.object.category = "sink";
  recordDeclaredUnits(labels.object, 0.28, "provenance.json");
  AnnotationDocument doc(std::make_shared<Mesh>(test::box({0, 0, 0}, {3.0f, 2.0f, 3.0f})), labels,
                         dir / "labels.json");
  EXPECT_TRUE(doc.unitsKnown());
  EXPECT_FLOAT_EQ(doc.metersPerUnit(), 0.28f);
  EXPECT_FALSE(recordedUnitGuess(doc.labels().object));
  doc.execute(std::make_unique<SetUnitsCommand>(0.3));
  EXPECT_FALSE(readLabels(dir / "labels.json").object.extra.contains(kUnitsDeclaredByField));
  doc.undo();
  EXPECT_EQ(
      readLabels(dir / "labels.json").object.extra.value(kUnitsDeclaredByField, std::string()),
      "provenance.json");
}

TEST(CategoryCommands, ASwitchIsOneUndoableStep) {
  const auto dir = test::freshTempDir();
  ObjectLabels labels;
  labels.object.category = "none";
  AnnotationDocument doc(std::make_shared<Mesh>(test::box({0, 0, 0}, {1, 1, 1})), labels, dir / "labels.json");
  doc.execute(std::make_unique<SetCategoryCommand>("stove"));
  EXPECT_EQ(readLabels(dir / "labels.json").object.category, "stove");
  doc.undo();
  EXPECT_EQ(doc.labels().object.category, "none");
}

}  // namespace
}  // namespace sagrid::ui
