// `sagrid annotate MESH|DIR|LIST --out DIR`: predicts affordance points for each mesh with the
// models of its category and writes OUT/<id>/labels.json, as a resumable batch: --shard I/N
// splits a collection between array tasks, objects already done are skipped, every outcome goes
// to OUT/annotate.jsonl (core/annotate/annotate_batch.h). Parsing and progress display only.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/cli_switch.h"
#include "app/command_registry.h"
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
    int symmetries = sagrid::AnnotateOptions{}.symmetries;
    bool force = false;
    std::optional<bool> coarseToFine;
    bool noPrintedMarks = false, noMirrorPairs = false, noAnchoredPairs = false,
         noRepeatedParts = false, noSpoutOutlets = false, noPartOwnership = false;
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
  cmd->add_option("--models", o->models, "Model folder (default: the installed models)");
  cmd->add_option("--cache", o->cache, "Feature cache folder (default: none)");
  sagrid::app::addUpAxisOption(*cmd, o->up, sagrid::app::kDetectedUpDefault);
  cmd->add_option("--instances", o->instances,
                  "auto (local minima + suppression), single (argmin, as the paper)")
      ->check(CLI::IsMember({"auto", "single"}));
  cmd->add_option("--symmetries", o->symmetries,
                  "Test-time augmentation: average each field over this many symmetric copies "
                  "of the object (z quarter turns x reflections; 1 = off, 8 = all, the default)")
      ->check(CLI::Range(1, 8));
  sagrid::app::addOptionalSwitch(
      cmd, "--coarse-to-fine,!--no-coarse-to-fine", o->coarseToFine,
      "Second pass on a crop around each model's points, so a small part on a large "
      "object is located at its own scale (about 0.5 s more per model)"
      " (default: as each model's card says, point_extraction.coarse_to_fine)");
  cmd->add_flag("--no-printed-marks", o->noPrintedMarks,
                "Switch the texture pass off: cooking zones and touch symbols printed on a "
                "stove's top (glass hobs) are not taken as its heat-source and toggle points");
  cmd->add_flag("--no-mirror-pairs", o->noMirrorPairs,
                "Switch the mirror-pair pass off: on a mirror-symmetric object the automatic count "
                "does not add the twin of a point whose neighbourhood has the same shape there");
  cmd->add_flag("--no-anchored-pairs", o->noAnchoredPairs,
                "Within the mirror-pair pass, do not pair a toggle button across the spout beside "
                "it (a mixer's hot and cold handles)");
  cmd->add_flag("--no-repeated-parts", o->noRepeatedParts,
                "Switch the repeated-parts pass off: a point on a small part of the mesh does not "
                "give a point on every copy of that part (a row of equal knobs), and a point at a "
                "mixer's spout is not moved onto its pair of handles");
  cmd->add_flag("--no-spout-outlets", o->noSpoutOutlets,
                "Switch the spout-outlet pass off: a fluid-source point on a faucet's handle or "
                "body is not moved to the outlet under the spout's tip near it");
  cmd->add_flag("--no-part-ownership", o->noPartOwnership,
                "Switch the part-ownership pass off: points of two types may share a small part "
                "(a burner point on a knob), and knob and burner points on the grate or a panel "
                "are kept");
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
    options.symmetries = o->symmetries;
    options.coarseToFine = o->coarseToFine;
    options.printedMarks = !o->noPrintedMarks;
    options.mirrorPairs = !o->noMirrorPairs;
    options.anchoredPairs = !o->noAnchoredPairs;
    options.repeatedParts = !o->noRepeatedParts;
    options.spoutOutlets = !o->noSpoutOutlets;
    options.partOwnership = !o->noPartOwnership;
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
