#include "core/annotate/category_rules.h"

namespace sagrid {

CategoryRules categoryRulesFor(const std::string& category) {
  CategoryRules rules;
  if (category != "stove") {
    rules.partOwnership.onePointPerPart = false;
    rules.partOwnership.strayRowSpacings = 0.0f;
    rules.spoutControls.reachVoxels = 10.0f;
    return rules;
  }
  rules.printedMarks = true;
  rules.repeatedParts.separationBySpacing = true;
  rules.repeatedParts.snapPartVoxels = 1.0f;
  rules.repeatedParts.sureKnobRow = 3;
  rules.repeatedParts.rowContinuationScale = 1.5f;
  RepeatedPartSettings caps;
  caps.roundFlatSeeds = true;
  caps.maxCopyScale = 1.5f;
  caps.pairReachVoxels = 0.0f;
  rules.burnerCaps = caps;
  return rules;
}

}  // namespace sagrid
