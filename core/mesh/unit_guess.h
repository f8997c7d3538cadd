// Units of files that do not say (issue 41): in-the-wild meshes are in metres, centimetres,
// millimetres or inches, and a stove 90 units tall is in centimetres. The guess takes the unit
// under which the object's largest extent is a plausible size for its category (one size range
// per category, wide enough for a cooktop and a range, a tap and a vanity), preferring the more
// common unit where several fit. Curators confirm or set it in the GUI; mass estimates and exports
// use object.meters_per_unit.
#pragma once

#include <string>
#include <vector>

namespace sagrid {

struct UnitGuess {
  double metersPerUnit = 1.0;
  std::string unit;    // "m", "cm", "mm" or "in"
  bool sure = false;   // only this unit puts the object in its category's range
  std::string reason;  // one line for labels.json and the GUI
};

struct PlausibleSize {
  double minMeters = 0;  // largest extent
  double maxMeters = 0;
};

// A unit the guess and the GUI's units list name.
struct NamedUnit {
  const char* name;
  double metersPerUnit;
};
// m, cm, mm, in: in the order a tie between fitting units is broken (how often in-the-wild files
// use each).
const std::vector<NamedUnit>& namedUnits();
// The name of `metersPerUnit` among namedUnits() (within a millionth), else "custom".
std::string unitName(double metersPerUnit);

// The range of largest extents the guess accepts for "stove", "sink" or anything else ("none").
PlausibleSize plausibleSize(const std::string& category);

// `largestExtent` in file units (> 0).
UnitGuess guessMetersPerUnit(double largestExtent, const std::string& category);

// How many times the larger of two positive scales or sizes is the smaller (>= 1): how far a
// guess is from the curated units, or a size from the one expected.
double scaleRatio(double a, double b);

// Game files are in no real unit (a kit scaled so its counters are 1.3 units high, a fridge 448
// units tall), and many are plausible in metres, so no size range tells. Where the sizes of
// curated objects that look alike (core/annotate/size_memory.h) put the object at
// `expectedMeters`, a named unit that makes it more than `farFactor` times larger or smaller gives
// way to the scale that makes it that size (unit "custom", not sure: a curator's units for the
// source replace it). `size` is the object's size in file units in the measure expected (`measure`
// names it in the reason: "largest extent", "height", ...). Otherwise, and for expectations or
// sizes that are not positive, `guess`.
UnitGuess unlessFarFromExpectedSize(const UnitGuess& guess, double size, double expectedMeters,
                                    double farFactor, const char* measure = "largest extent");

}  // namespace sagrid
