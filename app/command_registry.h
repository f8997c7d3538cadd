// Subcommands register themselves here, one file each under app/commands/, so adding a command
// never touches main.cpp. A command's setup adds its CLI11 subcommand with options and a
// callback that calls into core/ or ui/.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sagrid::app {

struct CommandEntry {
  std::string name;  // used only to order --help
  std::function<void(CLI::App& root)> setup;
};

std::vector<CommandEntry>& commandRegistry();
bool registerCommand(std::string name, std::function<void(CLI::App& root)> setup);

}  // namespace sagrid::app

#define SAGRID_REGISTER_COMMAND(name, setupFunction) \
  static const bool sagridCommandRegistered_##setupFunction = \
      ::sagrid::app::registerCommand(name, setupFunction)
