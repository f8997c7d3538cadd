// `sagrid annotate MESH|DIR --out DIR`: predicts affordance points for each mesh with the models
// of its category and writes OUT/<id>/labels.json; `sagrid filter DIR --like CATEGORY` ranks
// meshes by descriptor similarity to a category. Parsing and progress display only.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/command_registry.h"
#include "app/progress_bar.h"
#include "core/annotate/annotate.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/resource_paths.h"
#include "core/mesh/mesh_files.h"
#include "core/mesh/mesh_import.h"

namespace {
namespace fs = std::filesystem;

using sagrid::defaultModelsDir;  // ./resources, <bin>/../share/sagrid or the source tree

void setupAnnotate(CLI::App& root) {
  auto* cmd = root.add_subcommand("annotate",
                                  "Predict affordance points (heat sources, fluid sources, toggle "
                                  "buttons) for a mesh or every mesh "
                                  "in a folder and write OUT/<id>/labels.json (status predicted, "
                                  "with confidence and model source).");
  struct Options {
    std::string input, out, category, models, cache, up, instances = "auto";
    std::vector<std::string> counts;
    int symmetries = sagrid::AnnotateOptions{}.symmetries;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("input", o->input, "Mesh file or folder of meshes")->required();
  cmd->add_option("--out", o->out, "Output folder")->required();
  cmd->add_option("--category", o->category,
                  "Object category (default: chosen by descriptor retrieval)");
  cmd->add_option("--models", o->models, "Model folder (default resources/models)");
  cmd->add_option("--cache", o->cache, "Feature cache folder (default: none)");
  cmd->add_option("--up", o->up,
                  "Up axis of the file: x, -x, y, -y, z or -z (write --up=-y for negative "
                  "axes); default: y for glTF/GLB, else detected from the geometry")
      ->check([](const std::string& v) {
        return sagrid::parseUpAxis(v) ? std::string() : "must be x, -x, y, -y, z or -z, got " + v;
      });
  cmd->add_option("--instances", o->instances,
                  "auto (local minima + suppression), single (argmin, as the paper)")
      ->check(CLI::IsMember({"auto", "single"}));
  cmd->add_option("--symmetries", o->symmetries,
                  "Test-time augmentation: average each field over this many symmetric copies "
                  "of the object (z quarter turns x reflections; 1 = off, 8 = all, the default)")
      ->check(CLI::Range(1, 8));
  cmd->add_option("--count", o->counts,
                  "Known instance count per type, e.g. --count heatsource=5 (k-means)");
  cmd->callback([o] {
    const auto models =
        sagrid::ModelSet::load(o->models.empty() ? defaultModelsDir() : fs::path(o->models));
    sagrid::AnnotateOptions options;
    options.category = o->category;
    options.symmetries = o->symmetries;
    options.confidence = sagrid::readConfidenceCalibration(
        o->models.empty() ? defaultModelsDir() : fs::path(o->models));
    options.features = models.featureOptions();
    options.features.cacheDir = o->cache;
    if (!o->up.empty()) options.features.up = sagrid::parseUpAxis(o->up);
    options.mode =
        o->instances == "single" ? sagrid::InstanceMode::Single : sagrid::InstanceMode::Auto;
    for (const auto& c : o->counts) {
      const auto eq = c.find('=');
      int n = 0;
      try {
        n = eq == std::string::npos ? 0 : std::stoi(c.substr(eq + 1));
      } catch (const std::exception&) {
      }
      if (eq == std::string::npos || n < 1)
        throw sagrid::InvalidArgument("--count " + c +
                                      ": expected TYPE=N with N >= 1, e.g. heatsource=4");
      options.counts[c.substr(0, eq)] = n;
    }
    const auto files = sagrid::findMeshFiles(o->input);
    if (files.empty()) throw sagrid::FileError(o->input, "no mesh files found");
    sagrid::app::ProgressBar bar("annotate", files.size());
    std::size_t failed = 0, points = 0, rejected = 0;
    for (std::size_t i = 0; i < files.size(); ++i) {
      bar.update(i, files[i].id);
      const fs::path dir = fs::path(o->out) / files[i].id;
      try {
        const auto r = sagrid::annotateMeshFile(files[i].path, files[i].id, models, options, dir);
        fs::create_directories(dir);
        sagrid::writeLabels(dir / "labels.json", r.labels);
        points += r.labels.affordances.size();
        rejected += r.rejected;
        sagrid::logger()->info(
            "{}: {} ({}{:.3f}), {} points; import {:.2f} s, features {:.2f} s, models {:.3f} s",
            files[i].id, r.category, r.categoryRetrieved ? "retrieved, similarity " : "similarity ",
            r.categorySimilarity, r.labels.affordances.size(), r.importSeconds, r.featureSeconds,
            r.modelSeconds);
      } catch (const sagrid::Cancelled&) {
        throw;
      } catch (const sagrid::Error& e) {
        ++failed;
        bar.update(i + 1);
        std::fprintf(stderr, "\nsagrid: %s: failed: %s\n", files[i].path.string().c_str(),
                     e.what());
      }
    }
    bar.update(files.size());
    bar.finish();
    std::fprintf(stderr,
                 "annotated %zu of %zu objects (%zu points, %zu rejected as not a known "
                 "category) into %s%s\n",
                 files.size() - failed, files.size(), points, rejected, o->out.c_str(),
                 failed ? "; see the failures above" : "");
    if (failed == files.size()) throw sagrid::Error("every object failed");
  });
}

void setupFilter(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "filter",
      "Rank the meshes of a folder by cosine similarity of their object descriptor to a category's "
      "training mean (from the model cards), most similar first; objects the category classifier "
      "(category.json in the models folder) rejects as no known category come last, marked none.");
  struct Options {
    std::string input, like, models, cache, json;
    int top = 0;
    double threshold = -2;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("input", o->input, "Folder of meshes (or one mesh)")->required();
  cmd->add_option("--like", o->like, "Category to rank by, e.g. stove")->required();
  cmd->add_option("--models", o->models, "Model folder (default resources/models)");
  cmd->add_option("--cache", o->cache,
                  "Feature cache folder (default INPUT/.sagrid-cache for folders)");
  cmd->add_option("--top", o->top, "Print only the best N")->check(CLI::NonNegativeNumber);
  cmd->add_option("--min-similarity", o->threshold, "Print only meshes at least this similar");
  cmd->add_option("--json", o->json, "Also write the ranking as JSON");
  cmd->callback([o] {
    const auto models =
        sagrid::ModelSet::load(o->models.empty() ? defaultModelsDir() : fs::path(o->models));
    models.categoryMean(o->like);  // an unknown category fails here, before any work
    auto features = models.featureOptions();
    features.cacheDir = !o->cache.empty()            ? fs::path(o->cache)
                        : fs::is_directory(o->input) ? fs::path(o->input) / ".sagrid-cache"
                                                     : fs::path();
    const auto files = sagrid::findMeshFiles(o->input);
    struct Ranked {
      std::string id, path;
      double similarity;
      std::string best;  // the decided category ("none" when the classifier rejects it)
      bool rejected = false;
    };
    std::vector<Ranked> ranked;
    sagrid::app::ProgressBar bar("filter", files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
      bar.update(i, files[i].id);
      try {
        const auto f = sagrid::extractFeatures(files[i].path, features);
        const auto decision = models.decideCategory(f.descriptor);
        ranked.push_back({files[i].id, files[i].path.string(),
                          models.categorySimilarity(f.descriptor, o->like), decision.category,
                          decision.rejected});
      } catch (const sagrid::Error& e) {
        std::fprintf(stderr, "\nsagrid: %s: skipped: %s\n", files[i].path.string().c_str(),
                     e.what());
      }
    }
    bar.update(files.size());
    bar.finish();
    // Objects the category classifier rejects (not a stove or sink) rank after all others,
    // with the same threshold `annotate` uses.
    std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
      if (a.rejected != b.rejected) return b.rejected;
      return a.similarity > b.similarity;
    });
    nlohmann::json j = nlohmann::json::array();
    std::size_t shown = 0;
    for (const auto& r : ranked) {
      if (o->top > 0 && shown >= static_cast<std::size_t>(o->top)) break;
      if (r.similarity < o->threshold) continue;  // rejected objects follow, in their own order
      std::printf("%.4f  %-8s %s\n", r.similarity, r.best.c_str(), r.path.c_str());
      j.push_back({{"id", r.id},
                   {"mesh", r.path},
                   {"similarity", r.similarity},
                   {"closest_category", r.best},
                   {"rejected", r.rejected}});
      ++shown;
    }
    if (!o->json.empty()) sagrid::writeFileAtomic(o->json, j.dump(2) + "\n");
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("annotate", setupAnnotate);
SAGRID_REGISTER_COMMAND("filter", setupFilter);
