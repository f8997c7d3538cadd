// Points carried from a curated object of the same geometry: predictions to confirm that name
// their twin, a control's triangles kept only where both meshes list them alike, points and pivots
// moved onto a copy placed elsewhere, and one step that undo puts back exactly.
#include "ui/document/twin_points.h"

#include <gtest/gtest.h>

#include "core/annotate/suggested_points.h"
#include "core/annotate/units_record.h"
#include "core/controls/control_record.h"

namespace sagrid::ui {
namespace {

ObjectLabels curatedBasin() {
  ObjectLabels twin;
  twin.object.id = "basin_white";
  twin.object.category = "sink";
  AffordancePoint tap;
  tap.type = "fluidsource";
  tap.position = {0.1f, 0.2f, 0.3f};
  tap.status = AffordanceStatus::Edited;
  tap.source = "human";
  AffordancePoint handle;
  handle.type = "togglebutton";
  handle.position = {0.1f, 0.25f, 0.35f};
  handle.status = AffordanceStatus::Accepted;
  handle.confidence = 0.7f;
  handle.source = "sink.togglebutton@1a2b3c4d";
  handle.normal = Eigen::Vector3f(0, 0, 1);
  handle.extra[kControlField] = {{"motion", "lever"},
                                 {"part", {{"triangles", {{10, 4}}}}},
                                 {"axis", {1, 0, 0}},
                                 {"pivot", {0.1, 0.2, 0.35}}};
  twin.affordances = {tap, handle};
  twin.reviewState = ReviewState::Done;
  return twin;
}

TEST(TwinPoints, CarriedPointsArePredictionsNamingTheirTwin) {
  const std::vector<AffordancePoint> points = carriedPoints(curatedBasin(), "basin_white", true);
  ASSERT_EQ(points.size(), 2u);
  for (const AffordancePoint& p : points) {
    EXPECT_EQ(p.status, AffordanceStatus::Predicted);
    EXPECT_EQ(p.source, "carried:basin_white");
    EXPECT_FALSE(p.confidence);
  }
  EXPECT_EQ(points[0].position, Eigen::Vector3f(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(points[1].type, "togglebutton");
  // Triangles listed alike: the control's part means the same faces.
  EXPECT_EQ(points[1].extra[kControlField]["part"]["triangles"][0][0], 10);
  // Listed otherwise: the record goes, the part is found again.
  EXPECT_FALSE(
      carriedPoints(curatedBasin(), "basin_white", false)[1].extra.contains(kControlField));
}

TEST(TwinPoints, ACopyElsewhereGetsThePointsMovedOntoItsOwnSurface) {
  // The twin's mesh 240 units along x and 150 back along y of this one's (the origins' offset):
  // each point lands on the same spot of this copy, facing the same way, with its lever's pivot.
  const Eigen::Vector3f offset(-240.0f, 150.0f, 0.0f);
  const std::vector<AffordancePoint> points =
      carriedPoints(curatedBasin(), "basin_white", true, offset);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_TRUE(points[0].position.isApprox(Eigen::Vector3f(-239.9f, 150.2f, 0.3f), 1e-6f))
      << points[0].position.transpose();
  EXPECT_TRUE(points[1].position.isApprox(Eigen::Vector3f(-239.9f, 150.25f, 0.35f), 1e-6f));
  ASSERT_TRUE(points[1].normal);
  EXPECT_EQ(*points[1].normal, Eigen::Vector3f(0, 0, 1));
  const nlohmann::json& control = points[1].extra[kControlField];
  EXPECT_NEAR(control["pivot"][0].get<double>(), -239.9, 1e-4);
  EXPECT_NEAR(control["pivot"][1].get<double>(), 150.2, 1e-4);
  EXPECT_NEAR(control["pivot"][2].get<double>(), 0.35, 1e-6);
  EXPECT_EQ(control["axis"], nlohmann::json({1, 0, 0}));
  EXPECT_EQ(control["part"]["triangles"][0][0], 10);

  // The one step moves them alike.
  ObjectLabels labels;
  CarryTwinPointsCommand carry(curatedBasin(), "basin_white", true, std::nullopt, offset);
  carry.apply(labels);
  ASSERT_EQ(labels.affordances.size(), 2u);
  EXPECT_TRUE(labels.affordances[0].position.isApprox(points[0].position));
}

TEST(TwinPoints, OneStepTakesCategoryPointsUnitsAndRecordAndUndoPutsAllBack) {
  ObjectLabels labels;
  labels.object.id = "basin_blue";
  labels.object.category = "none";
  AffordancePoint suggested;
  suggested.type = "fluidsource";
  suggested.position = {0.5f, 0.5f, 0.5f};
  labels.affordances = {suggested};
  markSuggestions(labels, "sink");
  const nlohmann::json before = toJson(labels);

  UnitGuess units;
  units.metersPerUnit = 0.01;
  units.unit = "cm";
  units.reason = "as curated for basin_white, an object of the same geometry";
  CarryTwinPointsCommand carry(curatedBasin(), "basin_white", true, units);
  EXPECT_EQ(carry.description(), "points carried from basin_white (same geometry)");
  carry.apply(labels);
  EXPECT_EQ(labels.object.id, "basin_blue");
  EXPECT_EQ(labels.object.category, "sink");
  ASSERT_EQ(labels.affordances.size(), 2u);
  EXPECT_EQ(labels.affordances[1].type, "togglebutton");
  EXPECT_EQ(pointsCarriedFrom(labels), "basin_white");
  EXPECT_FALSE(suggestedCategory(labels));  // the prediction's suggestions went with its points
  const auto guess = recordedUnitGuess(labels.object);
  ASSERT_TRUE(guess);
  EXPECT_DOUBLE_EQ(guess->metersPerUnit, 0.01);
  EXPECT_DOUBLE_EQ(metersPerUnit(labels), 0.01);
  EXPECT_EQ(toJson(labels)["object"]["points_carried_from"], "basin_white");

  carry.revert(labels);
  EXPECT_EQ(toJson(labels), before);
  EXPECT_FALSE(pointsCarriedFrom(labels));

  // Units left alone where none are given (the object's own are known).
  CarryTwinPointsCommand withoutUnits(curatedBasin(), "basin_white", true, std::nullopt);
  withoutUnits.apply(labels);
  EXPECT_FALSE(recordedUnitGuess(labels.object));
  EXPECT_DOUBLE_EQ(metersPerUnit(labels), 1.0);
}

}  // namespace
}  // namespace sagrid::ui
