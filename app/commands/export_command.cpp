// `sagrid export LABELS_OR_DIR --format omnigibson|mjcf --out DIR [--collision none|hull|decompose]
// [--legacy-fluidsource] [--no-controls] [--mesh-root DIR]`: simulator exports, headless.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "app/command_registry.h"
#include "core/export/export_objects.h"

namespace {

void setupExport(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "export",
      "Export labelled objects for a simulator: OmniGibson/BEHAVIOR-1K (URDF with collision "
      "parts and mass, misc/metadata.json meta links) or MuJoCo/RoboCasa (MJCF with every mesh "
      "part, collision geoms, inertia and RoboCasa site names)");
  struct Options {
    std::string input, format, out, collision = "decompose", meshRoot;
    int maxParts = 32;
    bool legacyFluidSource = false, noControls = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("input", o->input,
                  "A labels.json, a mesh with labels.json beside it, or a folder of objects")
      ->required();
  cmd->add_option("--format", o->format, "omnigibson or mjcf")
      ->required()
      ->check(CLI::IsMember({"omnigibson", "mjcf"}));
  cmd->add_option("--out", o->out, "Output folder (one subfolder per object)")->required();
  cmd->add_option("--collision", o->collision,
                  "Collision geometry: none, hull (one convex hull) or decompose (convex parts "
                  "that keep basins and cavities open)")
      ->check(CLI::IsMember({"none", "hull", "decompose"}))
      ->capture_default_str();
  cmd->add_option("--max-parts", o->maxParts, "Most convex parts per object with decompose")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  cmd->add_flag("--legacy-fluidsource", o->legacyFluidSource,
                "OmniGibson: write fluid outlets as 'fluidsource' (OmniGibson before the "
                "'particlesource' rename)");
  cmd->add_flag("--no-controls", o->noControls,
                "Export toggle buttons as sites only, the body one rigid piece (by default each "
                "knob, lever or button is a moving part on its joint: knob_<loc>_joint, "
                "handle_joint; revolute or prismatic links in URDF)");
  cmd->add_option("--mesh-root", o->meshRoot,
                  "Folder the labels' object.mesh may lead into (e.g. the data folder of "
                  "`annotate --out` labels); by default a mesh must lie in the labels' folder");
  cmd->callback([o] {
    sagrid::ExportOptions options;
    options.collision = *sagrid::parseCollisionMode(o->collision);
    options.maxCollisionParts = o->maxParts;
    options.legacyFluidSource = o->legacyFluidSource;
    options.meshRoot = o->meshRoot;
    options.articulatedControls = !o->noControls;
    // One line per stage on stderr: enough to see a large mesh is moving, quiet otherwise.
    auto lastStage = std::make_shared<std::string>();
    options.progress = [lastStage](float fraction, const std::string& stage) {
      const std::string head = stage.substr(0, stage.find(':'));
      if (head == *lastStage) return;
      *lastStage = head;
      std::cerr << "sagrid: export: " << stage << " (" << static_cast<int>(fraction * 100)
                << " %)\n";
    };
    const auto results = sagrid::exportObjects(o->input, o->format, o->out, options);
    for (const auto& r : results) {
      for (const auto& w : r.warnings) std::cerr << "sagrid: warning: " << w << "\n";
      std::cout << r.mainFile.string() << "\n";
    }
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("export", setupExport);
