// `sagrid gui [PATHS...]` (the annotation GUI) and `sagrid render MESH --screenshot out.png`
// (the same frame, headless). Parsing only; the work is in ui/app.
#include <CLI/CLI.hpp>
#include <map>

#include "app/command_registry.h"
#include "core/mesh/import_time_limit.h"
#include "ui/app/app.h"
#include "ui/app/headless_render.h"

namespace {

void setupGui(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "gui", "Open the annotation GUI: review, fix and export affordance points");
  struct Options {
    std::vector<std::string> paths;
    std::string trainingSet = "training-set";
    bool noPredict = false, noFileName = false;
    std::string size = "1440x900";
    std::string models;
    std::string curationLog;
    bool noCurationLog = false;
  };
  auto options = std::make_shared<Options>();
  cmd->add_option("paths", options->paths,
                  "Mesh files and/or folders (a folder becomes the review queue)");
  cmd->add_option("--training-set", options->trainingSet,
                  "Dataset folder for 'Add to training set'")
      ->capture_default_str();
  cmd->add_flag("--no-predict", options->noPredict,
                "Do not run SAGrid automatically when an object opens");
  cmd->add_flag("--no-file-name", options->noFileName,
                "The category decision reads the shape alone, not the words of the mesh file's "
                "name (for a collection whose files are named for something else than they hold)");
  cmd->add_option("--models", options->models, "Model folder (default resources/models)");
  cmd->add_option("--size", options->size, "Window size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--curation-log", options->curationLog,
                  "Append every curator action to this JSON-lines log (default: curation.jsonl in "
                  "the first folder given, or beside the first file); read it with "
                  "`sagrid eval --curation LOG`");
  cmd->add_flag("--no-curation-log", options->noCurationLog, "Keep no curation log");
  cmd->callback([options] {
    // A stuck import is cancelled where assimp allows it; the GUI never ends the process (that
    // would lose unsaved work).
    sagrid::setImportTimeLimit({sagrid::importTimeLimit().seconds, false});
    sagrid::ui::ContextOptions contextOptions;
    sagrid::ui::parseSize(options->size, contextOptions.width, contextOptions.height);
    contextOptions.title = "SAGrid";
    auto context = sagrid::ui::createGlContext(sagrid::ui::GlBackend::Window, contextOptions);
    sagrid::ui::AppOptions appOptions;
    appOptions.recentFiles = sagrid::ui::RecentFiles::defaultStorage();
    appOptions.trainingSet = options->trainingSet;
    appOptions.autoPredict = !options->noPredict;
    appOptions.readFileName = !options->noFileName;
    appOptions.modelsDir = options->models.empty() ? sagrid::ui::ModelPredictor::defaultModelsDir()
                                                   : std::filesystem::path(options->models);
    sagrid::ui::App app(*context, appOptions);
    if (!options->noCurationLog && (!options->curationLog.empty() || !options->paths.empty())) {
      const std::filesystem::path first = options->paths.empty() ? "" : options->paths.front();
      const std::filesystem::path folder = std::filesystem::is_directory(first) ? first : first.parent_path();
      app.session().setCurationLog(options->curationLog.empty()
                                       ? (folder.empty() ? "." : folder) / "curation.jsonl"
                                       : std::filesystem::path(options->curationLog));
    }
    if (!options->paths.empty()) {
      app.session().openPaths(
          std::vector<std::filesystem::path>(options->paths.begin(), options->paths.end()));
    }
    app.run();
  });
}

void setupRender(CLI::App& root) {
  auto* cmd =
      root.add_subcommand("render",
                          "Render a mesh with its points (and distance field) to a PNG, "
                          "exactly as the GUI window draws it; headless with --backend egl");
  struct Options {
    sagrid::ui::RenderOptions render;
    std::string mesh, labels, screenshot, backend = "egl", size = "1280x800", fieldType, models;
    float yaw = 0, pitch = 0;
    int closeUp = 0;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("mesh", o->mesh, "Mesh file")->required();
  cmd->add_option("--labels", o->labels, "labels.json (default: the one beside the mesh)");
  cmd->add_flag("--field", o->render.showField,
                "Show the distance field (predicted, else of the labelled points)");
  cmd->add_option("--field-type", o->fieldType, "Show only this affordance type's field");
  cmd->add_option("--screenshot", o->screenshot, "PNG file to write")->required();
  cmd->add_option("--backend", o->backend, "egl (headless) or window")->capture_default_str();
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_flag(
      "--no-panels", [o](std::int64_t) { o->render.showPanels = false; }, "Draw only the 3D view");
  cmd->add_flag("--wireframe", o->render.wireframe, "Wireframe overlay");
  cmd->add_option("--turn", o->render.controlTurn,
                  "Draw every toggle button's control turned by this many radians (buttons "
                  "pressed), as the exports move them and View > Controls turned (T) shows")
      ->check(CLI::Range(-6.3, 6.3));
  cmd->add_option("--surface", o->render.surface,
                  "How the mesh is coloured: modelled, plain (View > Plain grey, G), material "
                  "(a colour per material, M) or contrast (each texture's contrast stretched, B)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, sagrid::ui::SurfaceColouring>{
              {"modelled", sagrid::ui::SurfaceColouring::Modelled},
              {"plain", sagrid::ui::SurfaceColouring::PlainGrey},
              {"material", sagrid::ui::SurfaceColouring::ByMaterial},
              {"contrast", sagrid::ui::SurfaceColouring::TextureContrast}},
          CLI::ignore_case));
  cmd->add_option("--models", o->models,
                  "Run SAGrid with the models in this folder first (predicted points and field)");
  auto* yaw = cmd->add_option("--yaw", o->yaw, "Camera azimuth in degrees about +z");
  auto* pitch = cmd->add_option("--pitch", o->pitch, "Camera elevation in degrees");
  auto* closeUp = cmd->add_option("--close-up", o->closeUp,
                                  "Frame point N (1-based, as the Points panel numbers them) in a "
                                  "close-up, as F does in the GUI");
  cmd->callback([o, yaw, pitch, closeUp] {
    sagrid::ui::RenderOptions& r = o->render;
    r.mesh = o->mesh;
    r.labels = o->labels;
    r.screenshot = o->screenshot;
    r.backend = sagrid::ui::parseGlBackend(o->backend);
    r.fieldType = o->fieldType;
    r.modelsDir = o->models;
    if (!o->fieldType.empty()) r.showField = true;
    sagrid::ui::parseSize(o->size, r.width, r.height);
    if (yaw->count()) r.yawDegrees = o->yaw;
    if (pitch->count()) r.pitchDegrees = o->pitch;
    if (closeUp->count()) r.closeUpPoint = o->closeUp;
    sagrid::ui::renderScreenshot(r);
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("gui", setupGui);
SAGRID_REGISTER_COMMAND("render", setupRender);
