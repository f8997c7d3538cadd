// `sagrid annotate MESH|DIR|LIST --out DIR`: predicts affordance points for each mesh with the
// models of its category and writes OUT/<id>/labels.json, as a resumable batch: --shard I/N
// splits a collection between array tasks, objects already done are skipped, every outcome goes
// to OUT/annotate.jsonl (core/annotate/annotate_batch.h). Parsing and progress display only.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/command_registry.h"
#include "app/commands/pass_options_flags.h"
#include "app/commands/up_axis_option.h"
#include "app/progress_bar.h"
#include "core/annotate/annotate_batch.h"
#include "core/annotate/category_classifier.h"
#include "core/annotate/object_list.h"
#include "core/annotate/run_manifest.h"
#include "core/common/error.h"
#include "core/common/resource_paths.h"
#include "core/mesh/mesh_import.h"

namespace {
namespace fs = std::filesystem;

using sagrid::defaultModelsDir;  // ./resources, <bin>/../share/sagrid or the source tree

std::map<std::string, int> parseCounts(const std::vector<std::string>& counts) {
  std::map<std::string, int> parsed;
  for (const auto& c : counts) {
    const auto eq = c.find('=');
    int n = 0;
    try {
      n = eq == std::string::npos ? 0 : std::stoi(c.substr(eq + 1));
    } catch (const std::exception&) {
    }
    if (eq == std::string::npos || n < 1)
      throw sagrid::InvalidArgument("--count " + c +
                                    ": expected TYPE=N with N >= 1, e.g. heatsource=4");
    parsed[c.substr(0, eq)] = n;
  }
  return parsed;
}

void setupAnnotate(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "annotate",
      "Predict affordance points (heat sources, fluid sources, toggle buttons) for a mesh, every "
      "mesh in a folder, or the objects of a list (`sagrid filter --list-out`), and write "
      "OUT/<id>/labels.json (status predicted, with confidence and model source). A batch "
      "resumes: objects whose labels match the mesh, models and options are skipped, curated "
      "labels are kept; each outcome is appended to OUT/annotate.jsonl. Each object runs in a "
      "worker process with a time limit, so a mesh that hangs or crashes the importer fails "
      "alone.");
  struct Options {
    std::string input, list, out, category, models, cache, up, instances = "auto", shard;
    std::vector<std::string> counts;
    bool force = false, noSuggestions = false, noFileName = false;
    sagrid::PassOptions passes;
    double timeLimit = 600;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("input", o->input,
                  "Mesh file, folder of meshes, or object list (.txt/.list: <id><TAB><mesh> or a "
                  "mesh path a line)");
  cmd->add_option("--list", o->list, "Object list to annotate (instead of INPUT)");
  cmd->add_option("--out", o->out, "Output folder")->required();
  cmd->add_option("--shard", o->shard,
                  "Only the objects of shard I of N (I/N, I counted from 0; split by a hash of "
                  "the object id, so every task agrees), e.g. $SLURM_ARRAY_TASK_ID/4");
  cmd->add_flag("--force", o->force,
                "Annotate again objects whose labels are up to date, and overwrite curated "
                "labels (points accepted, edited or added, or review done)");
  cmd->add_option("--time-limit", o->timeLimit,
                  "Seconds one object may take before it is stopped and recorded as failed "
                  "(0 = none)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--category", o->category,
                  "Object category (default: chosen by descriptor retrieval)");
  cmd->add_flag("--no-suggestions", o->noSuggestions,
                "An object the category decision rejects gets no points (by default it keeps its "
                "likeliest category's points, flagged as suggestions, for a curator to confirm)");
  cmd->add_flag("--no-file-name", o->noFileName,
                "The category decision reads the shape alone, not the words of the mesh file's "
                "name (for a collection whose files are named for something else than they hold)");
  cmd->add_option("--models", o->models, "Model folder (default: the installed models)");
  cmd->add_option("--cache", o->cache, "Feature cache folder (default: none)");
  sagrid::app::addUpAxisOption(*cmd, o->up, sagrid::app::kDetectedUpDefault);
  cmd->add_option("--instances", o->instances,
                  "auto (local minima + suppression), single (argmin, as the paper)")
      ->check(CLI::IsMember({"auto", "single"}));
  sagrid::app::addPassOptions(*cmd, o->passes);
  cmd->add_option("--count", o->counts,
                  "Known instance count per type, e.g. --count heatsource=5 (k-means)");
  cmd->callback([o] {
    if (o->input.empty() == o->list.empty())
      throw sagrid::InvalidArgument("give the objects either as INPUT or with --list FILE");
    const sagrid::Shard shard = o->shard.empty() ? sagrid::Shard{} : sagrid::parseShard(o->shard);
    sagrid::AnnotateBatchSettings settings;
    settings.modelsDir = o->models.empty() ? defaultModelsDir() : fs::path(o->models);
    settings.out = o->out;
    settings.force = o->force;
    auto& options = settings.options;
    options.category = o->category;
    static_cast<sagrid::PassOptions&>(options) = o->passes;
    options.suggestions = !o->noSuggestions;
    options.readFileName = !o->noFileName;
    // Models, their feature options and confidence map load in the worker process.
    options.features.cacheDir = o->cache;
    if (!o->up.empty()) options.features.up = sagrid::parseUpAxis(o->up);
    options.mode =
        o->instances == "single" ? sagrid::InstanceMode::Single : sagrid::InstanceMode::Auto;
    options.counts = parseCounts(o->counts);

    const auto all = sagrid::listObjects(o->list.empty() ? fs::path(o->input) : fs::path(o->list));
    if (all.empty())
      throw sagrid::FileError(o->list.empty() ? o->input : o->list, "no mesh files found");
    const auto files = sagrid::filesInShard(all, shard);

    sagrid::BatchOptions batch;
    batch.out = o->out;
    batch.shard = shard;
    batch.timeLimitSeconds = o->timeLimit;
    sagrid::app::ProgressBar bar(o->shard.empty() ? "annotate" : "annotate " + shard.toString(),
                                 files.size());
    batch.onProgress = [&bar](std::size_t done, const std::string& current) {
      bar.update(done, current);
    };
    std::size_t rejected = 0;
    batch.onOutcome = [&rejected](const nlohmann::json& line) {
      if (line.value("status", "") == sagrid::batch_status::kFailed)
        std::fprintf(stderr, "\nsagrid: %s: failed: %s\n", line.value("mesh", "").c_str(),
                     line.value("error", "").c_str());
      if (line.value("category", "") == sagrid::kRejectedCategory) ++rejected;
    };
    const auto summary = sagrid::runBatch(files, batch, sagrid::annotateWorkerSetup(settings));
    bar.update(files.size());
    bar.finish();
    using namespace sagrid::batch_status;
    std::printf(
        "annotate%s%s: annotated %zu of %zu objects (%zu up-to-date, %zu curated kept, %zu busy "
        "in another task, %zu failed; %zu points, %zu rejected as not a known category) into %s "
        "in %.1f s; manifest %s\n",
        o->shard.empty() ? "" : " shard ", o->shard.empty() ? "" : shard.toString().c_str(),
        summary.count(kAnnotated), files.size(), summary.count(kUpToDate), summary.count(kCurated),
        summary.count(kBusy), summary.count(kFailed), summary.points, rejected, o->out.c_str(),
        summary.seconds, (fs::path(o->out) / sagrid::kRunManifestFile).c_str());
    std::fflush(stdout);
    if (!files.empty() && summary.count(kFailed) == files.size())
      throw sagrid::Error("every object failed");
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("annotate", setupAnnotate);
