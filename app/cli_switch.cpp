#include "app/cli_switch.h"

#include <cstdint>

namespace sagrid::app {

CLI::Option* addOptionalSwitch(CLI::App* command, const std::string& names,
                               std::optional<bool>& said, const std::string& help) {
  // Called only when a flag is given: +1 per positive, -1 per negated one; the last word wins.
  return command->add_flag_function(
      names, [&said](std::int64_t count) { said = count > 0; }, help);
}

}  // namespace sagrid::app
