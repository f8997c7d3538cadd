#include "ui/document/units_commands.h"

#include <cstdio>

#include "core/annotate/units_record.h"

namespace sagrid::ui {

void SetUnitsCommand::apply(ObjectLabels& labels) {
  if (!labels.object.extra.is_object()) labels.object.extra = nlohmann::json::object();
  m_before = labels.object.extra;
  setCuratedUnits(labels.object, m_metersPerUnit);
}

void SetUnitsCommand::revert(ObjectLabels& labels) { labels.object.extra = m_before; }

std::string SetUnitsCommand::description() const {
  char text[64];
  std::snprintf(text, sizeof text, "set units to %.6g m per unit", m_metersPerUnit);
  return text;
}

}  // namespace sagrid::ui
