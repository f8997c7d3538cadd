// How labels.json records the units of a file that does not state them (issue 41):
// object.meters_per_unit_guess = {"unit", "meters_per_unit", "sure", "reason"}, and
// object.meters_per_unit set from the guess unless it is metres. A curator who sets the units
// (GUI, undoable) replaces the guess: the value stays, the guess record goes.
#pragma once

#include <optional>
#include <string>

#include "core/labels/labels.h"
#include "core/mesh/unit_guess.h"

namespace sagrid {

inline constexpr const char* kUnitGuessField = "meters_per_unit_guess";
inline constexpr const char* kUnitsDeclaredByField = "meters_per_unit_declared_by";

void recordUnitGuess(ObjectInfo& object, const UnitGuess& guess);

// The guess, when the object's units are guessed and not yet confirmed.
std::optional<UnitGuess> recordedUnitGuess(const ObjectInfo& object);

// The curator's units: object.meters_per_unit = metersPerUnit, the guess (or declaration) record
// removed.
void setCuratedUnits(ObjectInfo& object, double metersPerUnit);

// Units the object's source declares (a provenance.json beside the mesh: the Sweet Home 3D
// corpus writes its catalog's scale) stand without a guess: object.meters_per_unit, and
// object.meters_per_unit_declared_by naming the record.
void recordDeclaredUnits(ObjectInfo& object, double metersPerUnit, const std::string& declaredBy);

}  // namespace sagrid
