// `sagrid corpus sweethome3d --out DIR`: the real in-the-wild corpus from Debian's Sweet Home 3D
// packages (stoves, sinks, appliance distractors) as datasets real-train, real-val, distractors
// and unlabelled. `sagrid corpus wild --from POOL --out DIR`: the wild pool's meshes with their
// curated labels as wild-train, wild-val and unlabelled. Parsing and dispatch only; the work is
// in core/corpus.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>

#include "app/command_registry.h"
#include "app/progress_bar.h"
#include "core/common/error.h"
#include "core/common/resource_paths.h"
#include "core/corpus/sweethome3d_corpus.h"
#include "core/corpus/wild_pool_corpus.h"

namespace {
namespace fs = std::filesystem;

fs::path defaultDebCache() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return fs::path(xdg) / "sagrid" / "debs";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "sagrid" / "debs";
  return fs::temp_directory_path() / "sagrid-debs";
}

// --labels when given (it must exist), else the labels shipped in resources/datasets/<name>.
fs::path labelsFolder(const std::string& given, const std::string& name) {
  if (given.empty()) return sagrid::resourceDir("datasets/" + name);
  if (!fs::is_directory(given)) throw sagrid::FileError(given, "labels folder not found");
  return given;
}

// A corpus build's progress bar, made on its first report.
struct CorpusProgress {
  std::unique_ptr<sagrid::app::ProgressBar> bar;
  std::function<void(std::size_t, std::size_t, const std::string&)> callback() {
    return [this](std::size_t done, std::size_t total, const std::string& id) {
      if (!bar) bar = std::make_unique<sagrid::app::ProgressBar>("corpus", total);
      bar->update(done, id);
    };
  }
  void finish() {
    if (bar) bar->finish();
    bar.reset();
  }
};

void setupWildCorpus(CLI::App& corpus);

void setupCorpus(CLI::App& root) {
  auto* corpus =
      root.add_subcommand("corpus", "Build a real corpus of objects from a public source");
  corpus->require_subcommand(1);
  setupWildCorpus(*corpus);
  auto* cmd = corpus->add_subcommand(
      "sweethome3d",
      "Stoves, sinks and appliance distractors from Debian's Sweet Home 3D packages "
      "(sweethome3d-furniture libraries and the default catalog in sweethome3d.jar), written as "
      "datasets OUT/real-train, OUT/real-val (shipped labels), OUT/distractors, OUT/unlabelled, "
      "plus OUT/corpus.json. Uses the installed files, else downloads the .debs with apt-get "
      "download (no Java needed).");
  struct Options {
    std::string out, debs, labels, jar;
    std::vector<std::string> sh3f;
    bool nonFree = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--out", o->out, "Output folder (replaced only if empty or an earlier corpus)")
      ->required();
  cmd->add_option("--debs", o->debs, "Folder for downloaded .debs (default ~/.cache/sagrid/debs)");
  cmd->add_option("--sh3f", o->sh3f,
                  "Furniture library archive to read instead of the package (repeatable)");
  cmd->add_option("--jar", o->jar,
                  "sweethome3d.jar to read the default catalog from instead of the package");
  cmd->add_flag("--non-free", o->nonFree,
                "Also the libraries of sweethome3d-furniture-nonfree (Debian's non-free component; "
                "each model under its author's licence): installed, else downloaded through a "
                "private apt configuration that reads that component alone");
  cmd->add_option("--labels", o->labels,
                  "Shipped labels folder (<id>/labels.json, split.json); default "
                  "<source>/resources/datasets/sweethome3d");
  cmd->callback([o] {
    sagrid::SweetHome3dPackageOptions packages;
    packages.debCache = o->debs.empty() ? defaultDebCache() : fs::path(o->debs);
    for (const auto& f : o->sh3f) packages.sh3f.emplace_back(f);
    if (!o->jar.empty()) packages.jar = fs::path(o->jar);
    packages.nonFree = o->nonFree;
    const auto log = [](const std::string& line) {
      std::fprintf(stderr, "corpus: %s\n", line.c_str());
    };

    sagrid::SweetHome3dCorpusOptions options;
    options.out = o->out;
    options.sources = sagrid::locateSweetHome3dSources(packages, log);
    options.labelsDir = labelsFolder(o->labels, "sweethome3d");
    CorpusProgress progress;
    options.progress = progress.callback();
    const sagrid::CorpusSummary summary = sagrid::buildSweetHome3dCorpus(options);
    progress.finish();
    for (const auto& w : summary.warnings) std::fprintf(stderr, "corpus: warning: %s\n", w.c_str());
    auto count = [](const std::map<std::string, int>& m, const char* key) {
      const auto it = m.find(key);
      return it == m.end() ? 0 : it->second;
    };
    std::printf(
        "corpus: %zu objects -> %s (stove %d, sink %d, none %d; real-train %d, real-val %d, "
        "distractors %d, unlabelled %d; %zu warnings)\n",
        summary.objects.size(), o->out.c_str(), count(summary.countsByRole, "stove"),
        count(summary.countsByRole, "sink"), count(summary.countsByRole, "none"),
        count(summary.countsByDataset, "real-train"), count(summary.countsByDataset, "real-val"),
        count(summary.countsByDataset, "distractors"), count(summary.countsByDataset, "unlabelled"),
        summary.warnings.size());
  });
}

void setupWildCorpus(CLI::App& corpus) {
  auto* cmd = corpus.add_subcommand(
      "wild",
      "The wild pool (meshes from public repositories, as committed; ../shared/data/wild-pool) "
      "with the curated labels of resources/datasets/wild, written as datasets OUT/wild-train and "
      "OUT/wild-val (split by repository) and OUT/unlabelled, plus OUT/corpus.json. Checks every "
      "mesh's sha256 against its provenance and its labels.");
  struct Options {
    std::string from, out, labels;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--from", o->from, "The pool folder (one folder per object with provenance.json)")->required();
  cmd->add_option("--out", o->out, "Output folder (replaced only if empty or an earlier corpus)")->required();
  cmd->add_option("--labels", o->labels,
                  "Curated labels folder (<id>/labels.json, split.json); default "
                  "<source>/resources/datasets/wild");
  cmd->callback([o] {
    sagrid::WildCorpusOptions options;
    options.pool = o->from;
    options.out = o->out;
    options.labelsDir = labelsFolder(o->labels, "wild");
    CorpusProgress progress;
    options.progress = progress.callback();
    const sagrid::WildCorpusSummary summary = sagrid::buildWildCorpus(options);
    progress.finish();
    for (const auto& w : summary.warnings) std::fprintf(stderr, "corpus: warning: %s\n", w.c_str());
    std::string counts;
    for (const auto& [dataset, n] : summary.countsByDataset) counts += (counts.empty() ? "" : ", ") + dataset + " " + std::to_string(n);
    std::string categories;
    for (const auto& [category, n] : summary.countsByCategory)
      categories += (categories.empty() ? "" : ", ") + category + " " + std::to_string(n);
    std::printf("corpus: wild pool -> %s (%s; curated: %s; %zu warnings)\n", o->out.c_str(), counts.c_str(),
                categories.empty() ? "none" : categories.c_str(), summary.warnings.size());
  });
}

SAGRID_REGISTER_COMMAND("corpus", setupCorpus);

}  // namespace
