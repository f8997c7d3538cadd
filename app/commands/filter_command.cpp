// `sagrid filter DIR --like CATEGORY`: ranks the meshes of a collection by descriptor similarity
// to a category, and writes the candidates as an object list for `sagrid annotate --list`.
// Descriptors come from the descriptor cache when they can (core/features/descriptor_cache.h).
// Parsing and progress display only.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/command_registry.h"
#include "app/commands/up_axis_option.h"
#include "app/progress_bar.h"
#include "core/annotate/model_set.h"
#include "core/annotate/object_list.h"
#include "core/annotate/shard.h"
#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/common/resource_paths.h"
#include "core/features/descriptor_cache.h"
#include "core/mesh/mesh_import.h"

namespace {
namespace fs = std::filesystem;

void setupFilter(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "filter",
      "Rank the meshes of a folder (or an object list) by cosine similarity of their object "
      "descriptor to a category's training mean (from the model cards), most similar first; "
      "objects the category classifier (category.json in the models folder) rejects as no known "
      "category come last, marked none. Descriptors are cached (--cache), so a second pass over "
      "a collection only reads them.");
  struct Options {
    std::string input, like, models, cache, json, listOut, shard, up;
    int top = 0;
    double threshold = -2;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("input", o->input, "Folder of meshes, one mesh, or an object list (.txt)")
      ->required();
  cmd->add_option("--like", o->like, "Category to rank by, e.g. stove")->required();
  cmd->add_option("--models", o->models, "Model folder (default: the installed models)");
  cmd->add_option("--cache", o->cache,
                  "Feature cache folder (default INPUT/.sagrid-cache for folders)");
  sagrid::app::addUpAxisOption(*cmd, o->up, sagrid::app::kDetectedUpDefault);
  cmd->add_option("--top", o->top, "Keep only the best N")->check(CLI::NonNegativeNumber);
  cmd->add_option("--min-similarity", o->threshold, "Keep only meshes at least this similar");
  cmd->add_option("--json", o->json, "Also write the ranking as JSON");
  cmd->add_option("--list-out", o->listOut,
                  "Write the kept meshes whose decided category is the --like one (not another "
                  "category, not rejected as none) as an object list for "
                  "`sagrid annotate --list FILE`");
  cmd->add_option("--shard", o->shard,
                  "Only the objects of shard I of N (I/N, I from 0), split by object id");
  cmd->callback([o] {
    const auto models = sagrid::ModelSet::load(o->models.empty() ? sagrid::defaultModelsDir()
                                                                 : fs::path(o->models));
    models.categoryMean(o->like);  // an unknown category fails here, before any work
    auto features = models.featureOptions();
    if (!o->up.empty()) features.up = sagrid::parseUpAxis(o->up);
    features.cacheDir = !o->cache.empty()            ? fs::path(o->cache)
                        : fs::is_directory(o->input) ? fs::path(o->input) / ".sagrid-cache"
                                                     : fs::path();
    auto files = sagrid::listObjects(o->input);
    if (!o->shard.empty()) files = sagrid::filesInShard(files, sagrid::parseShard(o->shard));
    struct Ranked {
      sagrid::MeshFile file;
      double similarity = 0;
      std::string best;  // the decided category ("none" when the classifier rejects it)
      bool rejected = false;
    };
    std::vector<Ranked> ranked;
    std::size_t cached = 0;
    const auto start = std::chrono::steady_clock::now();
    sagrid::app::ProgressBar bar("filter", files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
      bar.update(i, files[i].id);
      try {
        auto source = sagrid::DescriptorSource::Computed;
        const auto inputs = models.categoryInputSet();
        const auto object = sagrid::extractObjectDescriptor(
            files[i].path, features, &source, inputs.topRelief, inputs.partStatistics);
        if (source != sagrid::DescriptorSource::Computed) ++cached;
        const auto& descriptor = object.descriptor;
        const auto decision = models.decideCategory(object, files[i].path);
        ranked.push_back({files[i], models.categorySimilarity(descriptor, o->like),
                          decision.category, decision.rejected});
      } catch (const sagrid::Error& e) {
        std::fprintf(stderr, "\nsagrid: %s: skipped: %s\n", files[i].path.string().c_str(),
                     e.what());
      }
    }
    bar.update(files.size());
    bar.finish();
    const double seconds = sagrid::secondsSince(start);
    // Objects the category classifier rejects (not a stove or sink) rank after all others,
    // with the same threshold `annotate` uses.
    std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
      if (a.rejected != b.rejected) return b.rejected;
      return a.similarity > b.similarity;
    });
    nlohmann::json j = nlohmann::json::array();
    std::vector<sagrid::MeshFile> candidates;
    std::size_t shown = 0;
    for (const auto& r : ranked) {
      if (o->top > 0 && shown >= static_cast<std::size_t>(o->top)) break;
      if (r.similarity < o->threshold) continue;  // rejected objects follow, in their own order
      std::printf("%.4f  %-8s %s\n", r.similarity, r.best.c_str(), r.file.path.c_str());
      j.push_back({{"id", r.file.id},
                   {"mesh", r.file.path.string()},
                   {"similarity", r.similarity},
                   {"closest_category", r.best},
                   {"rejected", r.rejected}});
      if (!r.rejected && r.best == o->like) candidates.push_back(r.file);
      ++shown;
    }
    if (!o->json.empty()) sagrid::writeFileAtomic(o->json, j.dump(2) + "\n");
    if (!o->listOut.empty()) sagrid::writeObjectList(o->listOut, candidates);
    std::fprintf(stderr,
                 "filter: %zu of %zu objects ranked (%zu descriptors from the cache) in %.1f s, "
                 "%.1f objects/s; %zu kept%s%s\n",
                 ranked.size(), files.size(), cached, seconds,
                 seconds > 0 ? static_cast<double>(files.size()) / seconds : 0.0, shown,
                 o->listOut.empty() ? "" : ", candidates listed in ", o->listOut.c_str());
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("filter", setupFilter);
