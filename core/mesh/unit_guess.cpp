#include "core/mesh/unit_guess.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace sagrid {

namespace {

// How far, in log10, `meters` lies outside the range (0 inside).
double outside(double meters, const PlausibleSize& range) {
  if (meters < range.minMeters) return std::log10(range.minMeters / meters);
  if (meters > range.maxMeters) return std::log10(meters / range.maxMeters);
  return 0.0;
}
}  // namespace

const std::vector<NamedUnit>& namedUnits() {
  static const std::vector<NamedUnit> kUnits{{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}};
  return kUnits;
}

std::string unitName(double metersPerUnit) {
  for (const NamedUnit& unit : namedUnits())
    if (std::abs(metersPerUnit - unit.metersPerUnit) <= 1e-6 * unit.metersPerUnit) return unit.name;
  return "custom";
}

PlausibleSize plausibleSize(const std::string& category) {
  if (category == "stove") return {0.3, 1.5};  // a two-zone hob to a six-burner range
  if (category == "sink") return {0.1, 2.0};   // a tap to a double vanity
  return {0.1, 3.0};                           // a toaster to a tall fridge or a kitchen island
}

UnitGuess guessMetersPerUnit(double largestExtent, const std::string& category) {
  UnitGuess guess;
  if (!(largestExtent > 0) || !std::isfinite(largestExtent)) {
    guess.unit = "m";
    guess.reason = "no extent to judge; metres kept";
    return guess;
  }
  const PlausibleSize range = plausibleSize(category);
  double best = std::numeric_limits<double>::infinity();
  int fitting = 0;
  for (const NamedUnit& unit : namedUnits()) {
    const double off = outside(largestExtent * unit.metersPerUnit, range);
    if (off == 0) ++fitting;
    if (off < best) {
      best = off;
      guess.metersPerUnit = unit.metersPerUnit;
      guess.unit = unit.name;
    }
  }
  guess.sure = fitting == 1;
  char line[200];
  std::snprintf(line, sizeof line, "largest extent %.4g units: %.3g m in %s, %s the %s size range (%.2g-%.2g m)%s",
                largestExtent, largestExtent * guess.metersPerUnit, guess.unit.c_str(),
                best == 0 ? "within" : "nearest to", category == "stove" || category == "sink" ? category.c_str() : "appliance",
                range.minMeters, range.maxMeters, guess.sure ? "" : "; other units fit too");
  guess.reason = line;
  return guess;
}

double scaleRatio(double a, double b) { return std::max(a, b) / std::min(a, b); }

UnitGuess unlessFarFromExpectedSize(const UnitGuess& guess, double size, double expectedMeters,
                                    double farFactor, const char* measure) {
  if (!(size > 0) || !std::isfinite(size) || !(expectedMeters > 0) ||
      !std::isfinite(expectedMeters) || !(farFactor >= 1))
    return guess;
  const double meters = size * guess.metersPerUnit;
  if (scaleRatio(meters, expectedMeters) <= farFactor) return guess;
  UnitGuess scaled;
  scaled.metersPerUnit = expectedMeters / size;
  scaled.unit = unitName(scaled.metersPerUnit);
  scaled.sure = false;
  char line[240];
  std::snprintf(line, sizeof line,
                "%s %.4g units: %.3g m in %s, more than %.3gx from the %.3g m of curated "
                "objects like it; scaled to that",
                measure, size, meters, guess.unit.c_str(), farFactor, expectedMeters);
  scaled.reason = line;
  return scaled;
}

}  // namespace sagrid
