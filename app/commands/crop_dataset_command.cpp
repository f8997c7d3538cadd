// `sagrid crop-dataset`: the coarse-to-fine second pass's view of every labelled object (the
// region around each affordance type, cut out as an object of its own), as training data.
// Parsing and progress display only; the work is in core/training/crop_dataset.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "app/command_registry.h"
#include "app/progress_bar.h"
#include "core/training/crop_dataset.h"

namespace {

void setupCropDataset(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "crop-dataset",
      "Write, for every labelled object of a dataset and every affordance type on it, the crop the "
      "coarse-to-fine second pass would cut around that type's points (shifted at random, as after "
      "a "
      "first pass a few cm off) as an object of its own: training data for the second pass");
  struct Options {
    std::string data, out;
    sagrid::CropDatasetOptions crop;
    unsigned long long seed = 1;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--data", o->data, "Dataset folder (manifest.jsonl or object folders)")
      ->required();
  cmd->add_option("--out", o->out, "Output dataset folder")->required();
  cmd->add_option(
         "--margin", o->crop.margin,
         "Crop margin, share of the object's largest extent (as annotate --coarse-to-fine)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--jitter", o->crop.jitter,
                  "The crop moves by up to this share of the extent on each axis")
      ->check(CLI::Range(0.0, 0.5));
  cmd->add_option("--seed", o->seed, "Random seed of the shifts");
  cmd->callback([o] {
    o->crop.seed = o->seed;
    std::unique_ptr<sagrid::app::ProgressBar> bar;
    const auto summary =
        sagrid::writeCropDataset(o->data, o->out, o->crop, [&](int done, int total) {
          if (!bar)
            bar =
                std::make_unique<sagrid::app::ProgressBar>("crop", static_cast<std::size_t>(total));
          bar->update(static_cast<std::size_t>(done));
        });
    if (bar) bar->finish();
    std::fprintf(stderr,
                 "%d crops of %d objects written to %s (%d type regions skipped: too wide or too "
                 "few triangles)\n",
                 summary.crops, summary.objects, o->out.c_str(), summary.skipped);
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("crop-dataset", setupCropDataset);
