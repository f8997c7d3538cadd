// The --up option of the commands that read mesh files: one of x, -x, y, -y, z, -z, checked when
// parsed; `defaultText` says what an unset axis means for that command.
#pragma once

#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace sagrid::app {

CLI::Option* addUpAxisOption(CLI::App& cmd, std::string& target, const std::string& defaultText);

// The default of commands that detect the axis like `annotate`.
inline constexpr const char* kDetectedUpDefault = "y for glTF/GLB, else detected from the geometry";

}  // namespace sagrid::app
