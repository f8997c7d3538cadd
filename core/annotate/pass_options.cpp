#include "core/annotate/pass_options.h"

namespace sagrid {

const std::vector<NamedPass>& namedPasses() {
  static const std::vector<NamedPass> passes = {
      {"printed_marks", &PassOptions::printedMarks},   {"mirror_pairs", &PassOptions::mirrorPairs},
      {"anchored_pairs", &PassOptions::anchoredPairs}, {"repeated_parts", &PassOptions::repeatedParts},
      {"spout_controls", &PassOptions::spoutControls}, {"spout_outlets", &PassOptions::spoutOutlets},
      {"part_ownership", &PassOptions::partOwnership}};
  return passes;
}

std::vector<std::string> passesOff(const PassOptions& passes) {
  std::vector<std::string> off;
  for (const auto& pass : namedPasses())
    if (!(passes.*pass.on)) off.push_back(pass.name);
  return off;
}

}  // namespace sagrid
