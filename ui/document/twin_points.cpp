#include "ui/document/twin_points.h"

#include "core/annotate/suggested_points.h"
#include "core/annotate/units_record.h"
#include "core/common/json_number.h"
#include "core/controls/control_record.h"

namespace sagrid::ui {

namespace {

// A control record's pivot moved by `offset`; a record without a readable one is left as it is
// (it is read, and reported, when the control is used).
void movePivot(nlohmann::json& control, const Eigen::Vector3f& offset) {
  if (!control.is_object()) return;
  const auto pivot = control.find("pivot");
  if (pivot == control.end() || !pivot->is_array() || pivot->size() != 3) return;
  for (int a = 0; a < 3; ++a)
    if (!(*pivot)[std::size_t(a)].is_number()) return;
  for (int a = 0; a < 3; ++a) {
    auto& value = (*pivot)[std::size_t(a)];
    value = jsonNumber(value.get<float>() + offset[a]);
  }
}

}  // namespace

std::optional<std::string> pointsCarriedFrom(const ObjectLabels& labels) {
  const auto it = labels.object.extra.find(kPointsCarriedFromField);
  if (it == labels.object.extra.end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}

std::vector<AffordancePoint> carriedPoints(const ObjectLabels& twin, const std::string& twinId,
                                           bool sameTriangleOrder, const Eigen::Vector3f& offset) {
  std::vector<AffordancePoint> points = twin.affordances;
  for (AffordancePoint& p : points) {
    p.position += offset;
    p.status = AffordanceStatus::Predicted;
    p.source = "carried:" + twinId;
    p.confidence.reset();  // a model's figure for the twin, not for this object
    p.extra.erase(kSuggestionField);
    if (!sameTriangleOrder)
      p.extra.erase(kControlField);
    else if (p.extra.contains(kControlField))
      movePivot(p.extra[kControlField], offset);
  }
  return points;
}

CarryTwinPointsCommand::CarryTwinPointsCommand(const ObjectLabels& twin, std::string twinId,
                                               bool sameTriangleOrder,
                                               std::optional<UnitGuess> units,
                                               const Eigen::Vector3f& offset)
    : m_twinId(std::move(twinId)),
      m_category(twin.object.category),
      m_points(carriedPoints(twin, m_twinId, sameTriangleOrder, offset)),
      m_units(std::move(units)) {}

void CarryTwinPointsCommand::apply(ObjectLabels& labels) {
  m_before = labels;
  labels.object.category = m_category;
  labels.affordances = m_points;
  if (!labels.object.extra.is_object()) labels.object.extra = nlohmann::json::object();
  labels.object.extra.erase(kSuggestedCategoryField);  // the prediction's, gone with its points
  if (m_units) recordUnitGuess(labels.object, *m_units);
  labels.object.extra[kPointsCarriedFromField] = m_twinId;
}

std::string CarryTwinPointsCommand::description() const {
  return "points carried from " + m_twinId + " (same geometry)";
}

}  // namespace sagrid::ui
