// `sagrid units memory --data DIR...`: the size memory the units guess recalls
// (core/annotate/size_memory.h) built from curated real objects, the size it recalls, how many
// objects and its far factor chosen leaving each source out, and written into the models folder
// only where that beats the named units alone. Parsing and progress display only.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "app/command_registry.h"
#include "app/progress_bar.h"
#include "core/annotate/model_set.h"
#include "core/annotate/size_memory.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/resource_paths.h"
#include "core/eval/size_memory_update.h"
#include "core/eval/units_cases.h"

namespace fs = std::filesystem;

namespace {

std::vector<std::string> defaultMeasureSetNames() {
  std::vector<std::string> names;
  for (const auto& set : sagrid::defaultMeasureSets()) {
    std::string name;
    for (const sagrid::SizeMeasure m : set) name += (name.empty() ? "" : ",") + std::string(sagrid::sizeMeasureName(m));
    names.push_back(name);
  }
  return names;
}

struct MemoryOptions {
  std::vector<std::string> data;
  std::string models, out, cache, report, into;
  std::vector<double> factors = sagrid::defaultFarFactors();
  // Each a set of measures (comma-separated) a memory may recall, the most agreed of them.
  std::vector<std::string> measureSets = defaultMeasureSetNames();
  std::vector<int> neighbours = sagrid::defaultNeighbourCounts();
};

std::vector<std::vector<sagrid::SizeMeasure>> parseMeasureSets(const std::vector<std::string>& sets) {
  std::vector<std::vector<sagrid::SizeMeasure>> parsed;
  for (const auto& set : sets) {
    std::vector<sagrid::SizeMeasure> measures;
    std::size_t start = 0;
    while (start <= set.size()) {
      const std::size_t comma = std::min(set.find(',', start), set.size());
      measures.push_back(sagrid::sizeMeasureNamed(set.substr(start, comma - start)));
      start = comma + 1;
    }
    parsed.push_back(std::move(measures));
  }
  return parsed;
}

void setupUnits(CLI::App& root) {
  auto* cmd = root.add_subcommand("units", "Units of files that do not state them");
  cmd->require_subcommand(1);
  auto o = std::make_shared<MemoryOptions>();
  auto* memory = cmd->add_subcommand(
      "memory",
      "Remember the real sizes of the curated objects of --data (their labels' units) "
      "for the units guess; evaluate it leaving each source out, choose so what it "
      "recalls (--measures, --neighbours) and its far factor (--factors), and write "
      "units_memory.json into --out only where it guesses units right more often than "
      "the named units alone, object by object, beyond the noise of that pairing");
  memory->add_option("--data", o->data, "Curated dataset folder (repeatable)");
  memory->add_option("--into", o->into,
                     "Grow the memory of this models folder: its objects join --data's (an object "
                     "curated again replaces its earlier entry); --out defaults to it");
  memory->add_option("--models", o->models,
                     "Models folder whose feature configuration the descriptors use (default "
                     "resources/models)");
  memory->add_option("--out", o->out,
                     "Folder to write units_memory.json into (default --into, else --models)");
  memory->add_option("--cache", o->cache, "Feature cache folder");
  memory->add_option("--report", o->report, "Also write the evaluation to REPORT/units_memory.md");
  memory->add_option("--factors", o->factors, "Candidate far factors (>= 1)")
      ->check(CLI::Range(1.0, 1e9));
  memory->add_option("--measures", o->measureSets,
                     "Candidate sets of measures the memory may recall, comma-separated, the one "
                     "its recalled objects agree on most (largest_extent, height, work_surface; "
                     "repeatable)")
      ->capture_default_str();
  memory->add_option("--neighbours", o->neighbours,
                     "Candidate numbers of curated objects of the category the memory recalls "
                     "(their median size), each judged leaving sources out (repeatable)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  memory->callback([o] {
    const auto measureSets = parseMeasureSets(o->measureSets);
    const fs::path modelsDir = o->models.empty() ? sagrid::defaultModelsDir() : fs::path(o->models);
    const auto models = sagrid::ModelSet::load(modelsDir);
    sagrid::FeatureOptions features = models.featureOptions();
    features.cacheDir = o->cache;
    const std::string hash = models.featureConfigHash();
    if (o->data.empty() && o->into.empty())
      throw sagrid::InvalidArgument("units memory needs --data DIR, --into MODELS or both");
    std::optional<sagrid::SizeMemory> grown;
    if (!o->into.empty()) {
      grown = sagrid::readSizeMemory(o->into);
      if (!grown)
        throw sagrid::InvalidArgument("--into " + o->into + ": no " + sagrid::kSizeMemoryFile + " there");
      if (grown->featureConfigHash() != hash)
        throw sagrid::InvalidArgument("--into " + o->into + ": its memory was built with other "
                                      "features than the models of --models");
    }
    std::vector<fs::path> folders(o->data.begin(), o->data.end());
    std::unique_ptr<sagrid::app::ProgressBar> bar;
    const auto curated = sagrid::readUnitsCases(
        folders, features, [&](std::size_t done, std::size_t total, const std::string& id) {
          if (!bar) bar = std::make_unique<sagrid::app::ProgressBar>("units", total);
          bar->update(done, id);
          if (done == total) bar.reset();
        });
    const auto update = sagrid::updateSizeMemory(grown ? &*grown : nullptr, curated,
                                                 sagrid::recallCandidates(measureSets, o->neighbours, o->factors),
                                                 hash);
    const std::string md = sagrid::unitsLosoMarkdown(update.report);
    std::cout << md;
    if (!o->report.empty()) {
      fs::create_directories(o->report);
      sagrid::writeFileAtomic(fs::path(o->report) / "units_memory.md", md);
    }
    const fs::path out = !o->out.empty() ? fs::path(o->out) : !o->into.empty() ? fs::path(o->into) : modelsDir;
    if (!update.memory) {
      std::fprintf(stderr, "%s; nothing written\n", update.verdict.c_str());
      return;
    }
    fs::create_directories(out);
    sagrid::writeSizeMemory(*update.memory, out);
    std::fprintf(stderr, "%s -> %s\n", update.verdict.c_str(), (out / sagrid::kSizeMemoryFile).c_str());
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("units", setupUnits);
