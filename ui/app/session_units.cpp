// The Session's units (issue 41): the curator's value for the open object, and the units a
// curator set carried to the other objects of the same source.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/annotate/units_record.h"
#include "core/dataset/object_source.h"
#include "core/mesh/unit_guess.h"
#include "ui/app/session.h"
#include "ui/document/units_commands.h"

namespace sagrid::ui {

bool Session::setUnits(double metersPerUnit) {
  if (!m_document) return false;
  if (!std::isfinite(metersPerUnit) || !(metersPerUnit > 0) || metersPerUnit > 1e6) {
    char text[160];
    std::snprintf(text, sizeof text, "units: %g metres per unit is not a size (a number above 0 is)",
                  metersPerUnit);
    reportError(text);
    return false;
  }
  execute(std::make_unique<SetUnitsCommand>(metersPerUnit));
  m_unitsCarried = false;  // the curator's now: no prediction replaces them
  return true;
}

std::string Session::sourceOfOpenObject() const {
  return m_document ? objectSource(m_document->labels(), m_document->meshPath(), "") : std::string();
}

// A size guess that only one unit fits (a fridge 1.8 units tall is in metres) stands where the
// source's units are more than twice or less than half of it: within a repository, scales differ
// (a microwave's 0.18 is no fridge's), while a kit's 0.69 over a metres guess is the kit's scale.
// Over the wild pool in queue order (tests/benchmarks/units_carry.py), fewer units actions than
// carrying always or never, whichever error a curator corrects.
bool carriedUnitsDisagree(double carried, const UnitGuess& own) {
  return own.sure && std::max(carried, own.metersPerUnit) > 2.0 * std::min(carried, own.metersPerUnit);
}

void Session::carryCuratedUnits() {
  m_unitsCarried = false;
  if (!m_document) return;
  const std::string source = sourceOfOpenObject();
  const auto carried = m_curatedUnits.find(source);
  if (source.empty() || carried == m_curatedUnits.end()) return;
  const std::optional<UnitGuess> guess = recordedUnitGuess(m_document->labels().object);
  if (m_document->unitsKnown() && !guess) return;  // the file's or a curator's units
  if (guess && carriedUnitsDisagree(carried->second, *guess)) return;
  if (guess && std::abs(guess->metersPerUnit - carried->second) <= 1e-9 * carried->second) return;
  UnitGuess fromSource;
  fromSource.metersPerUnit = carried->second;
  fromSource.unit = unitName(carried->second);
  fromSource.reason = "as the curator set them for another object of " + source + " this session" +
                      (guess ? " (the size guess said " + guess->unit + ")" : std::string());
  m_document->setUnitGuess(fromSource);
  m_unitsCarried = true;
}

}  // namespace sagrid::ui
