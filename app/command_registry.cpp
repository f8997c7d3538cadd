#include "app/command_registry.h"

namespace sagrid::app {

std::vector<CommandEntry>& commandRegistry() {
  static std::vector<CommandEntry> entries;
  return entries;
}

bool registerCommand(std::string name, std::function<void(CLI::App& root)> setup) {
  commandRegistry().push_back({std::move(name), std::move(setup)});
  return true;
}

}  // namespace sagrid::app
