// The numbers a simulator export takes from labels.json, validated where they enter (issue 14):
// metres per unit, the curator's mass and the affordance positions. Nothing non-finite or absurd
// reaches an MJCF, URDF or metadata.json; every problem names the labels file and the field.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/labels/labels.h"

namespace sagrid::exportdetail {

inline constexpr double kMinMetersPerUnit = 1e-6;  // micrometre units
inline constexpr double kMaxMetersPerUnit = 1e3;   // kilometre units
inline constexpr double kMaxCoordinateMeters = 1e4;
inline constexpr double kMaxMassKg = 1e6;

struct UnitScale {
  double metersPerUnit = 1.0;
  std::optional<std::string> warning;  // units unknown: metres assumed
};

// object.meters_per_unit (a finite number in [1e-6, 1e3]), else object.units / top-level "units"
// (m, cm, mm, in, ft), else metres with a warning. Throws FileError(labelsPath, ...) for a
// meters_per_unit that is not such a number and for units that are not text.
UnitScale exportUnitScale(const ObjectLabels& labels, const std::filesystem::path& labelsPath);

// The curator's mass, object.mass_kg (written by the GUI; a finite number in (0, 1e6] kg), or
// nullopt when absent. Throws FileError for anything else.
std::optional<double> curatedMassKg(const ObjectLabels& labels,
                                    const std::filesystem::path& labelsPath);

// Throws FileError naming affordance i when a position, scaled to metres, is not finite or lies
// farther than kMaxCoordinateMeters from the origin.
void validateAffordancePositions(const ObjectLabels& labels, double metersPerUnit,
                                 const std::filesystem::path& labelsPath);

}  // namespace sagrid::exportdetail
