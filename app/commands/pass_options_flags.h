// The options of the steps after each model (sagrid::PassOptions): --symmetries,
// --coarse-to-fine / --no-coarse-to-fine and a --no-<pass> flag per pass. `annotate` and `eval`
// take the same ones, so an evaluation can be asked for exactly what annotate ran.
#pragma once

namespace CLI {
class App;
}  // namespace CLI

namespace sagrid {
struct PassOptions;
}  // namespace sagrid

namespace sagrid::app {

// Binds the options to `passes` (which must outlive parsing); its values are the defaults.
void addPassOptions(CLI::App& cmd, PassOptions& passes);

}  // namespace sagrid::app
