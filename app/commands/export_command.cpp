// `sagrid export LABELS_OR_DIR --format omnigibson|mjcf --out DIR`: simulator exports, headless.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "app/command_registry.h"
#include "core/export/export_objects.h"

namespace {

void setupExport(CLI::App& root) {
  auto* cmd = root.add_subcommand("export",
                                  "Export labelled objects for a simulator: OmniGibson/BEHAVIOR-1K "
                                  "(URDF meta links + misc/metadata.json) or MuJoCo (MJCF sites)");
  struct Options {
    std::string input, format, out;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("input", o->input,
                  "A labels.json, a mesh with labels.json beside it, or a folder of objects")
      ->required();
  cmd->add_option("--format", o->format, "omnigibson or mjcf")
      ->required()
      ->check(CLI::IsMember({"omnigibson", "mjcf"}));
  cmd->add_option("--out", o->out, "Output folder (one subfolder per object)")->required();
  cmd->callback([o] {
    const auto results = sagrid::exportObjects(o->input, o->format, o->out);
    for (const auto& r : results) {
      for (const auto& w : r.warnings) std::cerr << "sagrid: warning: " << w << "\n";
      std::cout << r.mainFile.string() << "\n";
    }
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("export", setupExport);
