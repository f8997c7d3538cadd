// Bulk densities: the mass of a typical object of the category divided by the volume its outer
// surface encloses (what the voxel fill measures). Appliances are mostly air inside a steel or
// wooden shell, so these are far below the material densities they are built from.
//
// Sources and arithmetic (typical catalogue figures, rounded; an estimate to be edited in the
// GUI when the real object is known, not a measurement of any one product):
//  - stove: a 30-inch (76 cm) freestanding range is about 0.76 m x 0.66 m x 0.91 m = 0.46 m^3
//    and weighs about 55-90 kg in manufacturers' specification sheets -> ~150 kg/m^3. A built-in
//    cooktop (about 0.76 x 0.53 x 0.08 m = 0.032 m^3, 10-20 kg) would be ~450 kg/m^3; the range
//    figure is used since stoves in our data are mostly ranges.
//  - sink: a kitchen sink base with its countertop and a stainless basin, about 0.9 x 0.6 x 0.9 m
//    = 0.49 m^3 outer volume less the basin, 70-120 kg -> ~200 kg/m^3. A sink alone (a 0.8 mm
//    steel shell, 8-12 kg) comes out heavier per filled volume; the basin is not filled.
//  - faucet: a kitchen faucet of about 1-2 kg (brass body, catalogue weights) enclosing about
//    0.5-1 L -> ~2000 kg/m^3 (brass itself: 8400-8700 kg/m^3).
//  - default: 500 kg/m^3, the middle of furniture-like objects (softwood 400-600 kg/m^3, hollow
//    appliances 100-300 kg/m^3); water is 1000 kg/m^3.
#include <algorithm>
#include <string>

#include "core/common/ascii_case.h"
#include "core/physics/mass_properties.h"

namespace sagrid::physics {

const std::vector<DensityEntry>& densityTable() {
  static const std::vector<DensityEntry> table{
      {"stove", 150.0, "30-inch freestanding range: ~0.46 m^3 enclosed, 55-90 kg (spec sheets)"},
      {"sink", 200.0, "sink base with countertop and basin: ~0.49 m^3 enclosed, 70-120 kg"},
      {"faucet", 2000.0, "brass kitchen faucet: 1-2 kg enclosing 0.5-1 L"},
      {"default", 500.0, "furniture-like objects: wood 400-600 kg/m^3, hollow appliances 100-300"},
  };
  return table;
}

const DensityEntry& densityFor(std::string_view category) {
  const std::string lower = asciiLower(std::string(category));
  const auto& table = densityTable();
  for (const auto& entry : table)
    if (entry.category == lower) return entry;
  return table.back();
}

}  // namespace sagrid::physics
