#include "app/commands/up_axis_option.h"

#include <CLI/CLI.hpp>

#include "core/mesh/mesh_import.h"

namespace sagrid::app {

CLI::Option* addUpAxisOption(CLI::App& cmd, std::string& target, const std::string& defaultText) {
  return cmd
      .add_option("--up", target,
                  "Up axis of the file: x, -x, y, -y, z or -z (write --up=-y for negative axes); "
                  "default: " +
                      defaultText)
      ->check([](const std::string& v) {
        return parseUpAxis(v) ? std::string() : "must be x, -x, y, -y, z or -z, got " + v;
      });
}

}  // namespace sagrid::app
