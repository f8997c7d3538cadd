#include "core/annotate/units_record.h"

namespace sagrid {

void recordUnitGuess(ObjectInfo& object, const UnitGuess& guess) {
  object.extra[kUnitGuessField] = {{"unit", guess.unit},
                                   {"meters_per_unit", guess.metersPerUnit},
                                   {"sure", guess.sure},
                                   {"reason", guess.reason}};
  if (guess.metersPerUnit != 1.0) object.extra["meters_per_unit"] = guess.metersPerUnit;
  else object.extra.erase("meters_per_unit");
}

std::optional<UnitGuess> recordedUnitGuess(const ObjectInfo& object) {
  const auto it = object.extra.find(kUnitGuessField);
  if (it == object.extra.end() || !it->is_object()) return std::nullopt;
  UnitGuess guess;
  guess.unit = it->value("unit", std::string("m"));
  guess.metersPerUnit = it->value("meters_per_unit", 1.0);
  guess.sure = it->value("sure", false);
  guess.reason = it->value("reason", std::string());
  return guess;
}

void setCuratedUnits(ObjectInfo& object, double metersPerUnit) {
  object.extra["meters_per_unit"] = metersPerUnit;
  object.extra.erase(kUnitGuessField);
  object.extra.erase(kUnitsDeclaredByField);
}

void recordDeclaredUnits(ObjectInfo& object, double metersPerUnit, const std::string& declaredBy) {
  setCuratedUnits(object, metersPerUnit);
  object.extra[kUnitsDeclaredByField] = declaredBy;
}

}  // namespace sagrid
