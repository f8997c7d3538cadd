// Sane ranges for numbers read from files (labels, meshes, model cards). A value outside them is
// an error naming the file and the field where it enters, so no inf, NaN or null ever reaches a
// file we write or a number we draw.
#pragma once

#include <cmath>

namespace sagrid {

// Largest coordinate magnitude of a mesh vertex or a labelled point, in file units: beyond any
// object in any unit (a 1 m object in nanometres), far below float overflow when squared or
// summed (1e30 or 1e39 reached the viewport as inf and crashed its drawing).
inline constexpr double kMaxCoordinate = 1e9;
// meters_per_unit: from micrometres to kilometres.
inline constexpr double kMinMetersPerUnit = 1e-6;
inline constexpr double kMaxMetersPerUnit = 1e3;

inline bool isSaneCoordinate(double value) {
  return std::isfinite(value) && std::fabs(value) <= kMaxCoordinate;
}

}  // namespace sagrid
