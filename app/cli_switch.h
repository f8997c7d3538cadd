// A --name / --no-name switch whose absence means "not said", so a default from elsewhere (a
// model card) applies. CLI11 writes false into a std::optional<bool> given to add_flag even when
// neither flag is on the command line; this only sets the optional when one of them is.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace sagrid::app {

// `names` as for add_flag, e.g. "--coarse-to-fine,!--no-coarse-to-fine".
CLI::Option* addOptionalSwitch(CLI::App* command, const std::string& names,
                               std::optional<bool>& said, const std::string& help);

}  // namespace sagrid::app
