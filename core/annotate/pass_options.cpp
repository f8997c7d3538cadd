#include "core/annotate/pass_options.h"

#include <algorithm>
#include <set>

#include "core/common/error.h"

namespace sagrid {

const std::vector<NamedPass>& namedPasses() {
  static const std::vector<NamedPass> passes = {
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

std::vector<std::string> recordedPassesOff(const std::vector<std::string>& names) {
  static const std::set<std::string> removed = {"printed_marks",  "mirror_pairs",
                                                "anchored_pairs", "repeated_parts",
                                                "spout_controls", "spout_outlets",
                                                "part_ownership"};
  std::vector<std::string> off;
  for (const auto& name : names) {
    if (removed.count(name)) continue;
    if (std::none_of(namedPasses().begin(), namedPasses().end(),
                     [&](const NamedPass& p) { return name == p.name; }))
      throw InvalidArgument("passes_off names an unknown pass: " + name);
    off.push_back(name);
  }
  return off;
}

}  // namespace sagrid
