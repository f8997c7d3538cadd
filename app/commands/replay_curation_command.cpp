// `sagrid replay-curation PATHS --truth DIR --curation-log LOG`: a curator who knows the right
// labels (DIR/<id>/labels.json) reviews the objects of PATHS in the GUI's session, from the
// predictions in their labels.json, and the session's curation log records every action; then
// `sagrid eval --curation LOG` reports the throughput. With `--part-marks FILE` instead of
// --truth: the control parts a curator marked (ui/app/part_marks_replay.h) are made again in the
// labels.json of PATHS. Parsing only; the work is in ui/app.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "app/command_registry.h"
#include "core/common/error.h"
#include "core/curation/prediction_seed.h"
#include "core/io/json_file.h"
#include "core/labels/labels.h"
#include "ui/app/curation_replay.h"
#include "ui/app/model_predictor.h"
#include "ui/app/part_marks_replay.h"
#include "ui/app/session.h"
#include "ui/document/review_queue.h"

namespace {
namespace fs = std::filesystem;

struct ReplayOptions {
  std::vector<std::string> paths;
  std::string truth, log, models, predictions, partMarks;
  bool noRepredict = false;
};

// The GUI's session on PATHS as the replay drives it: no prediction on opening, its curation log
// (when given) marked replayed.
void openReplaySession(sagrid::ui::Session& session, const ReplayOptions& o) {
  session.autoPredict = false;
  session.logErrors = true;
  if (!o.log.empty()) session.setCurationLog(o.log, /*replayed=*/true);
  session.openPaths(std::vector<fs::path>(o.paths.begin(), o.paths.end()));
}

void printLines(const std::vector<std::string>& lines) {
  for (const auto& line : lines) std::fprintf(stderr, "replay-curation: %s\n", line.c_str());
}

void replayPartMarks(const ReplayOptions& o) {
  const nlohmann::json marks = sagrid::readJsonFile(o.partMarks);
  sagrid::ui::Session session;
  openReplaySession(session, o);
  const auto summary = sagrid::ui::replayPartMarks(session, marks, o.partMarks);
  printLines(session.pendingErrors());
  printLines(summary.problems);
  std::printf("replay-curation: %zu parts marked on %zu objects\n", summary.parts, summary.objects);
}

void setupReplayCuration(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "replay-curation",
      "Review PATHS (folders of objects whose labels.json hold the predictions) in the GUI's "
      "session as a curator who knows the right labels in --truth would: switch the category, set "
      "the units, drag, delete and add points (a row of them with copies or extend where that "
      "saves additions), accept; every action goes to the curation log. "
      "Changes the labels.json files of PATHS: run it on a copy.");
  auto o = std::make_shared<ReplayOptions>();
  cmd->add_option("paths", o->paths, "Folders or mesh files, as for sagrid gui")->required();
  cmd->add_option("--truth", o->truth, "Folder of right labels, <id>/labels.json");
  cmd->add_option("--part-marks", o->partMarks,
                  "Instead of --truth: a file of control parts a curator marked (per object "
                  "folder and toggle point: kept as found, or brush strokes, and the axis), made "
                  "again through the Points panel's Keep and the viewport's brush");
  cmd->add_option("--curation-log", o->log, "Curation log to append to (required with --truth)");
  cmd->add_option("--predictions", o->predictions,
                  "An `annotate --out` folder: its labels are first written beside the meshes they "
                  "describe (inside the first of PATHS), as the objects' starting point");
  cmd->add_option("--models", o->models, "Models that predict again after a category switch (default: the installed models)");
  cmd->add_flag("--no-repredict", o->noRepredict,
                "A category switch only drops the old points (the GUI before it predicted again)");
  cmd->callback([o] {
    if (!o->partMarks.empty()) {
      if (!o->truth.empty() || !o->predictions.empty())
        throw sagrid::InvalidArgument("replay-curation: --part-marks replays marks alone; give "
                                      "--truth and --predictions in a run of their own");
      replayPartMarks(*o);
      return;
    }
    if (o->truth.empty() || o->log.empty())
      throw sagrid::InvalidArgument("replay-curation needs --truth DIR and --curation-log LOG, or --part-marks FILE");
    if (!fs::is_directory(o->truth)) throw sagrid::FileError(o->truth, "labels folder not found");
    if (!o->predictions.empty()) {
      const std::size_t seeded =
          sagrid::seedPredictions(o->predictions, o->paths.front(), sagrid::ui::labelsPathFor);
      std::printf("replay-curation: %zu objects start from the predictions in %s\n", seeded, o->predictions.c_str());
    }
    sagrid::ui::Session session;
    sagrid::ui::ModelPredictor predictor(o->models.empty() ? sagrid::ui::ModelPredictor::defaultModelsDir()
                                                           : fs::path(o->models));
    session.setPredictorLookup([&predictor](const sagrid::ui::AnnotationDocument& doc) { return predictor.jobFor(doc); });
    openReplaySession(session, *o);
    const fs::path truthDir = o->truth;
    const auto summary = sagrid::ui::replayCuration(
        session,
        [&truthDir](const std::string& id) {
          const fs::path file = truthDir / id / "labels.json";
          return fs::is_regular_file(file) ? std::optional<sagrid::ObjectLabels>(sagrid::readLabels(file)) : std::nullopt;
        },
        !o->noRepredict);
    printLines(session.pendingErrors());
    std::printf("replay-curation: %zu objects reviewed, %zu without right labels (skipped), %zu failed; log %s\n",
                summary.objects, summary.withoutTruth, summary.failed, o->log.c_str());
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("replay-curation", setupReplayCuration);
