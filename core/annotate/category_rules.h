// What the passes do differently on each category: the one table of the category-specific rules.
// A stove's knobs and burner caps are parts of their own, its touch controls prints on its top; a
// sink's hot and cold handles are sometimes one part with the mixer's body, and the spokes of one
// cross handle are copies of one another. So the texture pass runs on stoves only, and the repeated-parts and part-ownership passes take per-category settings.
#pragma once

#include <optional>
#include <string>

#include "core/points/part_ownership.h"
#include "core/points/repeated_parts.h"
#include "core/points/spout_controls.h"

namespace sagrid {

struct CategoryRules {
  // Zones and touch symbols printed on the top stand for the heat sources and toggle buttons
  // (core/annotate/printed_marks_pass.h).
  bool printedMarks = false;
  // Stoves: copies as close as their spacing, knob points moved onto the knob parts
  // (RepeatedPartSettings::separationBySpacing, snapPartVoxels, sureKnobRow, rowContinuationScale).
  RepeatedPartSettings repeatedParts;
  // Stoves: after part ownership, heat-source points on a round flat cap repeat on its copies,
  // scaled ones too (a wok burner's), that hold no point of another type; unset = heat sources
  // are left as they are (roundFlatSeeds, maxCopyScale).
  std::optional<RepeatedPartSettings> burnerCaps;
  // Stoves: one point per part, strays from the full rows (onePointPerPart, strayRowSpacings; on
  // the generated wall-fixture sinks one point per part lost sink knobs).
  PartOwnershipSettings partOwnership;
  // Sinks: a toggle point on the spout's part moves to a small part beside it
  // (core/annotate/spout_controls_pass.h); off (reachVoxels 0) elsewhere.
  SpoutControlSettings spoutControls;
};

// The rules for objects of `category` (defaults for a category without any of its own).
CategoryRules categoryRulesFor(const std::string& category);

}  // namespace sagrid
