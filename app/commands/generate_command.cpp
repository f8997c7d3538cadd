// `sagrid generate`: procedural stoves and sinks with exact ground truth, in the dataset layout;
// `--preset bench` writes the fixed train/val split; `sagrid dataset-stats DIR` prints the
// variety table of a generated dataset.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/command_registry.h"
#include "app/progress_bar.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/generate/contact_sheet.h"
#include "core/generate/dataset_generator.h"
#include "core/generate/dataset_stats.h"

namespace {

void setupGenerate(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "generate",
      "Generate procedural stoves or sinks with exact affordance labels (dataset layout: one folder per "
      "object with mesh + labels.json, plus manifest.jsonl). The same seed and version give byte-identical "
      "files.");
  struct Options {
    std::string category, out, format = "mixed", contactSheet, preset;
    int count = 0;
    unsigned long long seed = 0;
    int sheetLimit = 64;
    bool stats = false;
    double wallFixtures = 0.0;
    double glassHobs = 0.0;
    bool appliances = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--category", o->category, "stove, sink or none (distractors: microwaves, ovens, dishwashers, hoods, cabinets)")
      ->check(CLI::IsMember({"stove", "sink", "none"}));
  cmd->add_option("--count", o->count, "Number of objects")->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", o->seed, "Random seed (object i depends only on seed, category and i)");
  cmd->add_option("--out", o->out, "Output dataset folder")->required();
  cmd->add_option("--format", o->format, "obj (z-up), glb (y-up) or mixed (half each)")
      ->check(CLI::IsMember({"obj", "glb", "mixed"}));
  cmd->add_option(
         "--preset", o->preset,
         "bench: the fixed benchmark split (OUT/train, OUT/val; see README); distractors: category "
         "\"none\" objects for the category classifier (OUT/train 150, OUT/val 50); "
         "distractors-appliances: the same with washing machines, toasters and countertop "
         "appliances among them; wall-fixtures: "
         "the dressed sinks the shipped sink models also train on (OUT/wall-fixtures 300); "
         "glass-hobs: stoves, half of them bare glass hobs (OUT/glass-hobs 300; the shipped stove "
         "models do not train on them, README: `generate --glass-hobs`); decision: the generated "
         "objects the point decision learns from beside the bench's val split (OUT/decision "
         "120)")
      ->check(CLI::IsMember({"bench", "distractors", "distractors-appliances", "wall-fixtures",
                             "glass-hobs", "decision"}));
  cmd->add_option(
         "--wall-fixtures", o->wallFixtures,
         "Share of sinks (not bare faucets) given a mirror, lamps, a shelf, a back panel or a "
         "towel bar on "
         "the wall behind them, as real vanities ship (0: the bench look; not with --preset)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--glass-hobs", o->glassHobs,
                  "Share of stoves that are built-in glass hobs on their own, zones and touch "
                  "controls printed only in the texture (not with --preset)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("--appliances", o->appliances,
                "Distractors (--category none): also washing machines and dryers, toasters, "
                "kettles, blenders and coffee makers (not with --preset)");
  cmd->add_option("--contact-sheet", o->contactSheet, "Also render a PNG grid of thumbnails with the labels drawn");
  cmd->add_option("--sheet-limit", o->sheetLimit, "At most this many objects on the contact sheet")->check(CLI::PositiveNumber);
  cmd->add_flag("--stats", o->stats, "Print the variety table of what was written");
  cmd->callback([o] {
    namespace fs = std::filesystem;
    const auto start = std::chrono::steady_clock::now();
    int written = 0;
    std::vector<fs::path> dirs;
    if (!o->preset.empty() && (o->wallFixtures > 0.0 || o->glassHobs > 0.0 || o->appliances)) {
      throw sagrid::InvalidArgument(
          "--wall-fixtures, --glass-hobs and --appliances change the objects; the presets are "
          "fixed splits");
    }
    if (!o->preset.empty()) {
      const auto& preset = o->preset == "bench"         ? sagrid::gen::benchPreset()
                           : o->preset == "distractors" ? sagrid::gen::distractorPreset()
                           : o->preset == "distractors-appliances"
                               ? sagrid::gen::applianceDistractorPreset()
                           : o->preset == "glass-hobs" ? sagrid::gen::glassHobPreset()
                           : o->preset == "decision"   ? sagrid::gen::decisionPreset()
                                                       : sagrid::gen::wallFixturePreset();
      int total = 0;
      for (const auto& s : preset)
        for (const auto& r : s.requests) total += r.count;
      sagrid::app::ProgressBar bar("generate", static_cast<std::size_t>(total));
      sagrid::gen::generatePreset(preset, o->out, [&](int done, int) { bar.update(static_cast<std::size_t>(done)); });
      bar.finish();
      written = total;
      for (const auto& s : preset) dirs.push_back(fs::path(o->out) / s.name);
    } else {
      if (o->category.empty()) throw sagrid::InvalidArgument("--category is required (or --preset bench)");
      sagrid::app::ProgressBar bar("generate " + o->category, static_cast<std::size_t>(o->count));
      sagrid::gen::generateDataset(
          {{o->category, o->count, o->seed, {o->wallFixtures, o->glassHobs, o->appliances}}},
          sagrid::gen::parseMeshFormat(o->format), o->out,
          [&](int done, int) { bar.update(static_cast<std::size_t>(done)); });
      bar.finish();
      written = o->count;
      dirs.push_back(o->out);
    }
    const double seconds = sagrid::secondsSince(start);
    std::fprintf(stderr, "generated %d objects in %.2f s (%.1f objects/s)\n", written, seconds,
                 seconds > 0 ? written / seconds : 0.0);
    if (!o->contactSheet.empty()) {
      sagrid::gen::writeDatasetContactSheet(dirs.front(), o->contactSheet, o->sheetLimit);
      std::fprintf(stderr, "contact sheet: %s\n", o->contactSheet.c_str());
    }
    if (o->stats) {
      for (const auto& d : dirs) std::cout << "# " << d.string() << "\n\n" << sagrid::gen::datasetStatsTable(d);
    }
  });
}

void setupDatasetStats(CLI::App& root) {
  auto* cmd = root.add_subcommand("dataset-stats", "Print the variety table (generator parameters, affordances, "
                                                   "units, formats, triangles) of a generated dataset");
  struct Options {
    std::string dir, contactSheet;
    int sheetLimit = 64, views = 1;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("dir", o->dir, "Dataset folder (manifest.jsonl, or object folders as in shared/data/real-dev)")
      ->required();
  cmd->add_option("--contact-sheet", o->contactSheet, "Also render a PNG grid of the objects with their labels drawn");
  cmd->add_option("--sheet-limit", o->sheetLimit, "At most this many objects on the contact sheet")->check(CLI::PositiveNumber);
  cmd->add_option("--views", o->views, "Views per object on the contact sheet (yaw steps)")->check(CLI::PositiveNumber);
  cmd->callback([o] {
    std::cout << sagrid::gen::datasetStatsTable(o->dir);
    if (!o->contactSheet.empty()) {
      sagrid::gen::ContactSheetOptions options;
      options.viewsPerItem = o->views;
      sagrid::gen::writeDatasetContactSheet(o->dir, o->contactSheet, o->sheetLimit, options);
    }
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("generate", setupGenerate);
SAGRID_REGISTER_COMMAND("dataset-stats", setupDatasetStats);
