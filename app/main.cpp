// sagrid: parses the command line and dispatches to the registered subcommands. Maps errors to
// exit codes: 0 success, 1 a sagrid error (message on one line), 2 bad command line, 130 cancel.
#include <algorithm>
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "app/command_registry.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/mesh/import_time_limit.h"
#include "core/mesh/mesh_import.h"

int main(int argc, char** argv) {
  CLI::App root{"SAGrid: simulation affordances (heat sources, fluid sources, toggle buttons) "
                "on 3D meshes"};
  root.set_version_flag("--version", std::string("sagrid ") + SAGRID_VERSION);
  root.require_subcommand(1);
  bool verbose = false, lenient = false;
  double importSeconds = 120;
  root.add_flag("-v,--verbose", verbose, "Log progress details to stderr");
  root.add_flag("--lenient", lenient,
                "Use what can be read of a truncated mesh file (with a warning) instead of "
                "refusing it");
  root.add_option("--import-time-limit", importSeconds,
                  "Seconds one mesh import may take (0 = no limit); a file that takes longer is "
                  "an error naming it")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  root.fallthrough();  // root options may follow the subcommand: sagrid info --lenient x.obj
  root.parse_complete_callback([&] {
    if (verbose) sagrid::setLogLevel(spdlog::level::info);
    sagrid::setLenientImportByDefault(lenient);
    // Where a loader ignores the cancel, the command line ends the process with the error.
    sagrid::setImportTimeLimit({importSeconds, true});
  });

  auto& entries = sagrid::app::commandRegistry();
  std::sort(entries.begin(), entries.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  for (const auto& entry : entries) entry.setup(root);

  try {
    root.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = root.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const sagrid::Cancelled&) {
    std::fprintf(stderr, "sagrid: cancelled\n");
    return 130;
  } catch (const sagrid::Error& e) {
    std::fprintf(stderr, "sagrid: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sagrid: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
