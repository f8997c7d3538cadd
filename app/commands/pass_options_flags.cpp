#include "app/commands/pass_options_flags.h"

#include <CLI/CLI.hpp>
#include <string>

#include "app/cli_switch.h"
#include "core/annotate/pass_options.h"

namespace sagrid::app {
namespace {
// The passes a --no-<name> flag switches off.
struct PassSwitch {
  const char* flag;
  bool PassOptions::*on;
  const char* help;
};
const PassSwitch kPassSwitches[] = {
    {"--no-printed-marks", &PassOptions::printedMarks,
     "Switch the texture pass off: cooking zones and touch symbols printed on a stove's top "
     "(glass hobs) are not taken as its heat-source and toggle points"},
    {"--no-mirror-pairs", &PassOptions::mirrorPairs,
     "Switch the mirror-pair pass off: on a mirror-symmetric object the automatic count does not "
     "add the twin of a point whose neighbourhood has the same shape there"},
    {"--no-anchored-pairs", &PassOptions::anchoredPairs,
     "Within the mirror-pair pass, do not pair a toggle button across the spout beside it (a "
     "mixer's hot and cold handles)"},
    {"--no-repeated-parts", &PassOptions::repeatedParts,
     "Switch the repeated-parts pass off: a point on a small part of the mesh does not give a "
     "point on every copy of that part (a row of equal knobs), and a point at a mixer's spout is "
     "not moved onto its pair of handles"},
    {"--no-spout-controls", &PassOptions::spoutControls,
     "Switch the spout-controls pass off: on a sink, a toggle point on the spout's part (where the "
     "fluid source is) is not moved to the handle or lever beside it"},
    {"--no-spout-outlets", &PassOptions::spoutOutlets,
     "Switch the spout-outlet pass off: a fluid-source point on a faucet's handle or body is not "
     "moved to the outlet under the spout's tip near it"},
    {"--no-point-scorer", &PassOptions::learnedDecision,
     "Switch the learned point decision off: where the models folder has a point scorer "
     "(point_scorer.json), its choice among the candidates does not replace the passes' points"},
    {"--no-part-ownership", &PassOptions::partOwnership,
     "Switch the part-ownership pass off: points of two types may share a small part (a burner "
     "point on a knob), and knob and burner points on the grate or a panel are kept"},
};
}  // namespace

void addPassOptions(CLI::App& cmd, PassOptions& passes) {
  cmd.add_option("--symmetries", passes.symmetries,
                 "Test-time augmentation: average each field over this many symmetric copies "
                 "of the object (z quarter turns x reflections; 1 = off, 8 = all, the default)")
      ->check(CLI::Range(1, 8));
  addOptionalSwitch(&cmd, "--coarse-to-fine,!--no-coarse-to-fine", passes.coarseToFine,
                    "Second pass on a crop around each model's points, so a small part on a large "
                    "object is located at its own scale (about 0.5 s more per model)"
                    " (default: as each model's card says, point_extraction.coarse_to_fine)");
  for (const auto& pass : kPassSwitches) {
    bool& on = passes.*pass.on;
    cmd.add_flag_callback(
        pass.flag, [&on] { on = false; }, pass.help);
  }
}

}  // namespace sagrid::app
