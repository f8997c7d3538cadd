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
    {"--no-point-scorer", &PassOptions::learnedDecision,
     "Switch the learned point decision off: where the models folder has a point scorer "
     "(point_scorer.json), its choice among the candidates does not replace the count's points"},
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
