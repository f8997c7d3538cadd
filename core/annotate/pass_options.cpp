#include "core/annotate/pass_options.h"

namespace sagrid {

namespace {

template <bool PassOptions::*on>
NamedPass switchedPass(const char* name) {
  return {name, [](const PassOptions& p) { return !(p.*on); },
          [](PassOptions& p) { p.*on = false; }};
}

}  // namespace

const std::vector<NamedPass>& namedPasses() {
  static const std::vector<NamedPass> passes = {
      switchedPass<&PassOptions::printedMarks>("printed_marks"),
      switchedPass<&PassOptions::mirrorPairs>("mirror_pairs"),
      switchedPass<&PassOptions::anchoredPairs>("anchored_pairs"),
      switchedPass<&PassOptions::repeatedParts>("repeated_parts"),
      switchedPass<&PassOptions::spoutControls>("spout_controls"),
      switchedPass<&PassOptions::spoutOutlets>("spout_outlets"),
      switchedPass<&PassOptions::partOwnership>("part_ownership"),
      {"coarse_to_fine",
       [](const PassOptions& p) { return p.coarseToFine.has_value() && !*p.coarseToFine; },
       [](PassOptions& p) { p.coarseToFine = false; }}};
  return passes;
}

std::vector<std::string> passesOff(const PassOptions& passes) {
  std::vector<std::string> off;
  for (const auto& pass : namedPasses())
    if (pass.isOff(passes)) off.push_back(pass.name);
  return off;
}

}  // namespace sagrid
