#include "core/eval/point_model_guard_by_source.h"

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/dataset/dataset_subset.h"
#include "core/dataset/object_source.h"
#include "core/eval/learning_curve.h"
#include "core/labels/labels.h"
#include "core/model/model_card.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

struct CuratedObject {
  DatasetEntry entry;
  std::size_t dataset = 0;  // index into the fine-tune's datasets
  std::string source;
  bool ofType = false;  // of the model's category, with points of its type: judged
};

}  // namespace

std::optional<GuardVerdict> judgeUpdateBySource(const PointModelGuardBySource& g) {
  if (g.folds < 2) throw InvalidArgument("the guard by source needs at least 2 folds");
  const auto [category, type] = model::splitModelName(g.fineTune.modelName);
  const auto& datasets = g.fineTune.datasets;
  std::vector<CuratedObject> objects;
  for (std::size_t d = 0; d < datasets.size(); ++d) {
    if (datasets[d].role != "data") continue;
    for (auto& entry : readDataset(datasets[d].dir, datasets[d].referenceRoot)) {
      const ObjectLabels labels = readLabels(entry.labels);
      if (entry.category.empty()) entry.category = labels.object.category;
      CuratedObject o{entry, d,
                      objectSource(labels, entry.mesh, datasets[d].dir.filename().string()),
                      entry.category == category && !labels.ofType(type).empty()};
      objects.push_back(std::move(o));
    }
  }
  // The folds: the sources of the objects judged; a source without any trains in every fold.
  std::vector<std::string> judgedSources;
  for (const auto& o : objects)
    if (o.ofType) judgedSources.push_back(o.source);
  const std::set<std::string> sources(judgedSources.begin(), judgedSources.end());
  if (sources.size() < 2) return std::nullopt;
  const auto split = sourceFoldSplit(judgedSources, g.folds, g.seed);

  GuardVerdict v;
  v.model = g.fineTune.modelName;
  v.judgedBySource = true;
  v.folds = static_cast<int>(split.size());
  v.sources.assign(sources.begin(), sources.end());
  std::vector<ObjectFigures> errors;  // per object judged, paired by id
  fs::remove_all(g.workDir);
  // The folds' subsets and candidates go when the guard ends, decided or interrupted.
  struct RemoveWhenDone {
    fs::path dir;
    ~RemoveWhenDone() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } removeWhenDone{g.workDir};
  for (std::size_t f = 0; f < split.size(); ++f) {
    if (g.onFold) g.onFold(static_cast<int>(f) + 1, static_cast<int>(split.size()));
    std::set<std::string> leftOut;
    for (std::size_t j : split[f]) leftOut.insert(judgedSources[j]);
    const fs::path foldDir = g.workDir / ("fold" + std::to_string(f + 1));
    // Each curated dataset without the fold's sources (its weight and feature cache kept), and
    // the fold's objects of the type per dataset (each read with its own cache).
    DatasetTrainingOptions fineTune = g.fineTune;
    fineTune.datasets.clear();
    fineTune.outDir = foldDir / "candidate";
    fineTune.command =
        g.fineTune.command + " (guard by source, fold " + std::to_string(f + 1) + ")";
    std::vector<GuardOptions> tests;
    for (std::size_t d = 0; d < datasets.size(); ++d) {
      const TrainingDataSource& source = datasets[d];
      if (source.role != "data") {
        fineTune.datasets.push_back(source);
        continue;
      }
      std::vector<const DatasetEntry*> training, test;
      std::vector<fs::path> files;
      for (const auto& o : objects) {
        if (o.dataset != d) continue;
        files.push_back(o.entry.mesh), files.push_back(o.entry.labels);
        if (!leftOut.count(o.source))
          training.push_back(&o.entry);
        else if (o.ofType)
          test.push_back(&o.entry);
      }
      TrainingDataSource subset = source;
      subset.referenceRoot = folderHoldingFiles(source.dir, files);
      if (subset.cacheDir.empty())
        subset.cacheDir = g.fineTune.features.cacheDir.empty() ? source.dir / ".sagrid-cache"
                                                               : g.fineTune.features.cacheDir;
      const fs::path subsetDir = foldDir / ("data" + std::to_string(d));
      if (!training.empty()) {
        subset.dir = subsetDir / "train";
        writeDatasetSubset(subset.dir, training);
        fineTune.datasets.push_back(subset);
      }
      if (!test.empty()) {
        writeDatasetSubset(subsetDir / "test", test);
        tests.push_back({g.currentDir, fineTune.outDir, v.model, subsetDir / "test",
                         subset.referenceRoot, subset.cacheDir, g.fineTune.features});
      }
    }
    fineTune.features.cacheDir.clear();  // per dataset (above)
    trainFromDataset(fineTune);
    for (const GuardOptions& test : tests) {
      const HeldOutError current = heldOutError(g.currentDir, test);
      const HeldOutError candidate = heldOutError(fineTune.outDir, test);
      for (const ObjectFigures& pair : pairById(current.byObject, candidate.byObject))
        errors.push_back(pair);
    }
  }
  const std::string judgedBy = std::to_string(errors.size()) + " curated object(s) of " +
                               std::to_string(sources.size()) + " sources, each of " +
                               std::to_string(v.folds) +
                               " folds of sources left out of the fine-tune in turn";
  if (errors.empty()) {
    v.currentError = v.candidateError = v.pairedNoise = NAN;
    v.reason = "no curated object of its type could be evaluated: current model kept";
    return v;
  }
  decideOnPairedErrors(v, errors, judgedBy);
  return v;
}

}  // namespace sagrid
