// The object's mass as the curator sets it in the Object panel: labels.json object.mass_kg
// (kilograms; absent = use the estimate from core/physics). The simulator exports read it
// (core/export/export_units.h, curatedMassKg) and scale the estimated inertia to it. Setting and
// clearing it are undoable commands like every other edit.
#pragma once

#include <optional>
#include <string>

#include "ui/document/command.h"

namespace sagrid::ui {

inline constexpr const char* kMassField = "mass_kg";  // in labels.json "object"

// The curated mass in labels (object.mass_kg), or nullopt when unset or not a number.
std::optional<double> curatedMass(const ObjectLabels& labels);

class SetMassCommand final : public Command {
 public:
  // `mass` nullopt clears object.mass_kg (back to the estimate).
  explicit SetMassCommand(std::optional<double> mass) : m_mass(mass) {}
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override;

 private:
  std::optional<double> m_mass;
  nlohmann::json m_before;  // object.mass_kg before, null when it was absent
};

}  // namespace sagrid::ui
