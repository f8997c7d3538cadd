#include "ui/document/control_commands.h"

#include "core/controls/control_record.h"

namespace sagrid::ui {

namespace {

void setRecord(AffordancePoint& point, const nlohmann::json& record) {
  if (!point.extra.is_object()) point.extra = nlohmann::json::object();
  if (record.is_null()) point.extra.erase(kControlField);
  else point.extra[kControlField] = record;
}

}  // namespace

void SetControlCommand::apply(ObjectLabels& labels) {
  if (m_index < 0 || static_cast<std::size_t>(m_index) >= labels.affordances.size()) return;
  AffordancePoint& point = labels.affordances[static_cast<std::size_t>(m_index)];
  m_before = point.extra.is_object() ? point.extra.value(kControlField, nlohmann::json()) : nlohmann::json();
  setRecord(point, m_record);
}

void SetControlCommand::revert(ObjectLabels& labels) {
  if (m_index < 0 || static_cast<std::size_t>(m_index) >= labels.affordances.size()) return;
  setRecord(labels.affordances[static_cast<std::size_t>(m_index)], m_before);
}

std::string SetControlCommand::description() const {
  return "control of point " + std::to_string(m_index + 1) + ": " + m_what;
}

}  // namespace sagrid::ui
