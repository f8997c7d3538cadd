// Points carried from a curated twin: an object of the same geometry
// (core/mesh/geometry_identity.h: the same triangles up to a translation; a colour variant, the
// same washbasin with another material) needs the same labels, so an object with none curated yet
// starts from its twin's points, category and units instead of the model's prediction. The points
// stay to confirm (status predicted: one key, A, accepts them) and labels.json records where they
// came from: object.points_carried_from = the twin's id. The Session finds the twin when an object
// opens (ui/app/session_twin.cpp). A twin may lie elsewhere in its file (the same mesh placed at
// another spot): its points move by `offset`, this object's geometry origin less the twin's
// (GeometryMatch::offset), so they land on the same spot of this copy.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/mesh/unit_guess.h"
#include "ui/document/command.h"

namespace sagrid::ui {

inline constexpr const char* kPointsCarriedFromField = "points_carried_from";

// The twin the object's points were carried from, when they were.
std::optional<std::string> pointsCarriedFrom(const ObjectLabels& labels);

// The twin's points as predictions to confirm, source "carried:<twin id>", moved by `offset`
// (file frame; normals and a control's axis keep their direction, its pivot moves). A control's
// record names triangles by index (core/controls/control_record.h): it is kept only where both
// meshes list their triangles in the same order; elsewhere the part is found again, as for a
// prediction.
std::vector<AffordancePoint> carriedPoints(const ObjectLabels& twin, const std::string& twinId,
                                           bool sameTriangleOrder,
                                           const Eigen::Vector3f& offset = Eigen::Vector3f::Zero());

// One undoable step: the twin's category and points, `units` (a guess naming the twin, where the
// object's own are not known) and the record. Undo puts the labels back as they were.
class CarryTwinPointsCommand final : public Command {
 public:
  CarryTwinPointsCommand(const ObjectLabels& twin, std::string twinId, bool sameTriangleOrder,
                         std::optional<UnitGuess> units,
                         const Eigen::Vector3f& offset = Eigen::Vector3f::Zero());
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override { labels = m_before; }
  std::string description() const override;

 private:
  std::string m_twinId;
  std::string m_category;
  std::vector<AffordancePoint> m_points;
  std::optional<UnitGuess> m_units;
  ObjectLabels m_before;
};

}  // namespace sagrid::ui
