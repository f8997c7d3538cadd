// The object's units as the curator sets them in the Object panel (issue 41): labels.json
// object.meters_per_unit, replacing a guess (core/annotate/units_record.h). Undoable like every
// edit; mass estimates, sizes and exports follow the value.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "ui/document/command.h"

namespace sagrid::ui {

class SetUnitsCommand final : public Command {
 public:
  explicit SetUnitsCommand(double metersPerUnit) : m_metersPerUnit(metersPerUnit) {}
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override;
  CurationAction curationAction() const override { return CurationAction::Units; }

 private:
  double m_metersPerUnit;
  nlohmann::json m_before;  // object.extra before
};

}  // namespace sagrid::ui
