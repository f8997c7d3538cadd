#include "ui/document/mass_commands.h"

#include <cstdio>

namespace sagrid::ui {

namespace {
void setField(ObjectLabels& labels, const nlohmann::json& value) {
  if (!labels.object.extra.is_object()) labels.object.extra = nlohmann::json::object();
  if (value.is_null()) {
    labels.object.extra.erase(kMassField);
  } else {
    labels.object.extra[kMassField] = value;
  }
}
}  // namespace

std::optional<double> curatedMass(const ObjectLabels& labels) {
  const auto& extra = labels.object.extra;
  if (!extra.is_object()) return std::nullopt;
  const auto it = extra.find(kMassField);
  if (it == extra.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

void SetMassCommand::apply(ObjectLabels& labels) {
  const auto& extra = labels.object.extra;
  m_before =
      extra.is_object() && extra.contains(kMassField) ? extra.at(kMassField) : nlohmann::json();
  setField(labels, m_mass ? nlohmann::json(*m_mass) : nlohmann::json());
}

void SetMassCommand::revert(ObjectLabels& labels) { setField(labels, m_before); }

std::string SetMassCommand::description() const {
  if (!m_mass) return "use the estimated mass";
  char text[64];
  std::snprintf(text, sizeof text, "set mass to %.3g kg", *m_mass);
  return text;
}

}  // namespace sagrid::ui
