// A toggle button's control as the curator changes it (issue 42): the point's "control" record
// (core/controls/control_record.h: its part, motion, axis, pivot and the burner it drives)
// replaced whole, undoable like every edit. The exports move the part as the record says.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "ui/document/command.h"

namespace sagrid::ui {

class SetControlCommand final : public Command {
 public:
  // `record` null removes the point's record (the exports then find the part themselves).
  SetControlCommand(int index, nlohmann::json record, std::string what)
      : m_index(index), m_record(std::move(record)), m_what(std::move(what)) {}
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override;
  int selectionAfterApply() const override { return m_index; }
  int selectionAfterRevert() const override { return m_index; }

 private:
  int m_index;
  nlohmann::json m_record, m_before;
  std::string m_what;
};

}  // namespace sagrid::ui
