#include "core/eval/point_scorer_update.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/annotate/model_set.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/eval/evaluation.h"
#include "core/generate/dataset_generator.h"
#include "core/training/training_sources.h"

namespace sagrid {

namespace fs = std::filesystem;

namespace {

// Every model's candidates on the objects of `dir`, made as `sagrid scorer candidates` makes them.
std::vector<CandidateSet> candidatesOf(const ModelSet& models, const fs::path& dir,
                                       const std::string& phase,
                                       const ScorerUpdateRequest& request) {
  EvaluationOptions options;
  options.keepCandidates = true;
  options.dataDir = dir;
  options.features = models.featureOptions();
  options.onProgress = [&](std::size_t done, std::size_t total, const std::string& id) {
    if (request.cancel && request.cancel->load()) throw Cancelled();
    if (request.onProgress) request.onProgress(phase, done, total, id);
  };
  return evaluateModels(models, options).candidateSets;
}

std::size_t withTruth(const std::vector<CandidateSet>& sets) {
  std::size_t n = 0;
  for (const auto& s : sets) n += !s.truth.empty();
  return n;
}

// "a -> b edits on WHERE (the current point decision -> the retrained one): adopted" (or where
// better, or refused).
std::string guardVerdict(const ScorerGuard& guard, bool hadCurrent, const std::string& where) {
  return std::to_string(guard.currentEdits) + " -> " + std::to_string(guard.newEdits) +
         " edits on " + where + " (" +
         (hadCurrent ? "the current point decision" : "the count's points") +
         " -> the retrained one): " +
         (!guard.adopted ? "refused, the current decision stays"
          : guard.adoptedWhole()
              ? "adopted"
              : "adopted where better (" + std::to_string(guard.adoptedEdits) +
                    " edits); kept the decision before for " + modelsWhere(guard, false));
}

}  // namespace

std::optional<ScorerGuard> guardPointScorerBySource(
    const PointScorer* current, const std::vector<const CandidateSet*>& training,
    const ScorerTrainingOptions& options, const std::function<void(int, int)>& onFold) {
  std::set<std::string> sources;
  for (const CandidateSet* set : training)
    if (!set->generated) sources.insert(set->source);
  if (sources.size() < 2) return std::nullopt;
  std::map<std::string, ScorerVerdict> byModel;  // each model's edits summed over the folds
  std::map<std::string, std::vector<ObjectFigures>> categoryEdits;  // each held-out object's
  int k = 0;
  for (const std::string& source : sources) {
    if (onFold) onFold(k++, static_cast<int>(sources.size()));
    std::vector<const CandidateSet*> rest;
    std::vector<CandidateSet> held;
    for (const CandidateSet* set : training) {
      if (!set->generated && set->source == source)
        held.push_back(*set);
      else
        rest.push_back(set);
    }
    const ScorerGuard fold = guardPointScorer(current, trainPointScorer(rest, options), held, rest);
    std::set<std::string> judged;
    for (const auto& set : held) judged.insert(set.model);
    for (const auto& [category, pairs] : fold.categoryEdits)
      categoryEdits[category].insert(categoryEdits[category].end(), pairs.begin(), pairs.end());
    for (const ScorerVerdict& v : fold.byModel) {
      if (!judged.count(v.model)) continue;
      ScorerVerdict& sum = byModel[v.model];
      sum.model = v.model;
      sum.currentEdits += v.currentEdits;
      sum.newEdits += v.newEdits;
      sum.handPoints += v.handPoints;
    }
  }
  std::map<std::string, PairedChange> byCategory;  // each object's edits, paired over the folds
  for (const auto& [category, pairs] : categoryEdits) byCategory[category] = pairedChange(pairs);
  std::map<std::string, std::size_t> judgedModels;
  for (const auto& [model, v] : byModel) ++judgedModels[categoryOfModel(model)];
  ScorerGuard guard;
  for (auto& [model, v] : byModel) {
    const std::string category = categoryOfModel(model);
    const PairedChange& change = byCategory[category];
    const auto edits = [&](double mean) {
      return static_cast<std::size_t>(std::lround(mean * static_cast<double>(change.objects)));
    };
    v.adopted = change.clearlyBetter();
    v.categoryCurrentEdits = edits(change.current);
    v.categoryAdoptedEdits = v.adopted ? edits(change.candidate) : v.categoryCurrentEdits;
    v.categoryJudged = judgedModels[category];
    v.categoryNoise = change.noise * static_cast<double>(change.objects);
    guard.currentEdits += v.currentEdits;
    guard.newEdits += v.newEdits;
    guard.adoptedEdits += v.adopted ? v.newEdits : v.currentEdits;
    guard.adopted = guard.adopted || v.adopted;
    guard.byModel.push_back(v);
  }
  guard.categoryEdits = std::move(categoryEdits);
  return guard;
}

ScorerUpdate judgeScorerUpdate(PointScorer fresh, const std::optional<PointScorer>& current,
                               const std::vector<CandidateSet>& heldOut,
                               const std::vector<const CandidateSet*>& training) {
  ScorerUpdate update;
  update.scorer = std::move(fresh);
  update.heldOutSets = heldOut.size();
  if (heldOut.empty()) {
    update.adoptedScorer = update.scorer;
    update.verdict = "unguarded: the retrained point decision is kept, better or not";
    return update;
  }
  const PointScorer* was = current ? &*current : nullptr;
  const ScorerGuard& guard = *(update.guard = guardPointScorer(was, update.scorer, heldOut, training));
  update.adoptedScorer = adoptedScorer(was, update.scorer, guard);
  update.verdict = guardVerdict(guard, current.has_value(), "the held-out objects");
  return update;
}

std::vector<fs::path> decisionGeneratedDirs(const fs::path& benchDir,
                                            const std::function<void(int, int)>& progress) {
  const auto generatedOnce = [&](const std::vector<gen::BenchSplit>& preset,
                                 const std::string& split) {
    if (!fs::exists(benchDir / split / "manifest.jsonl"))
      gen::generatePreset(preset, benchDir, progress);
    return benchDir / split;
  };
  return {generatedOnce(gen::benchPreset(), "val"),
          generatedOnce(gen::decisionPreset(), gen::decisionPreset().front().name)};
}

ScorerUpdate updatePointScorer(const ScorerUpdateRequest& request) {
  // Every folder before any candidate is made (minutes of work).
  for (const fs::path& dir : {request.curated, request.generated, request.heldOut})
    if (!dir.empty() && !fs::is_directory(dir)) throw FileError(dir, "dataset folder not found");
  const std::vector<fs::path> generatedDirs =
      request.generated.empty()
          ? decisionGeneratedDirs(defaultBenchDir(),
                                  [&](int done, int total) {
                                    if (request.onProgress)
                                      request.onProgress("bench", done, total, "");
                                  })
          : std::vector<fs::path>{request.generated};
  const ModelSet models = ModelSet::load(request.models);
  const auto curated = candidatesOf(models, request.curated, "curated", request);
  if (withTruth(curated) == 0)
    throw InvalidArgument("the curated objects of " + request.curated.string() +
                          " give the point decision nothing to learn: no object with points of "
                          "a model in " + request.models.string());
  std::vector<CandidateSet> generated;
  for (const fs::path& dir : generatedDirs)
    for (auto& set : candidatesOf(models, dir, "generated", request))
      generated.push_back(std::move(set));
  std::vector<const CandidateSet*> training;
  for (const auto& s : curated) training.push_back(&s);
  for (const auto& s : generated) training.push_back(&s);
  const auto heldOut = request.heldOut.empty()
                           ? std::vector<CandidateSet>{}
                           : candidatesOf(models, request.heldOut, "held out", request);
  const std::optional<PointScorer> current = readPointScorer(request.models);
  ScorerUpdate update =
      judgeScorerUpdate(trainPointScorer(training, request.training), current, heldOut, training);
  if (heldOut.empty()) {
    // No held-out folder: the curated objects judge, each source left out of the fitting in turn.
    int folds = 0;
    const auto guard = guardPointScorerBySource(
        current ? &*current : nullptr, training, request.training, [&](int k, int n) {
          if (request.cancel && request.cancel->load()) throw Cancelled();
          if (request.onProgress) request.onProgress("guard: source left out", k, n, "");
          folds = n;
        });
    if (guard) {
      update.guard = guard;
      // As on a held-out folder: the new scorer's models no curated object judged are listed,
      // not adopted.
      for (const auto& entry : update.scorer.byModel)
        if (std::none_of(guard->byModel.begin(), guard->byModel.end(),
                         [&](const ScorerVerdict& v) { return v.model == entry.first; }))
          update.guard->byModel.push_back({entry.first, 0, 0, 0, false});
      update.adoptedScorer =
          adoptedScorer(current ? &*current : nullptr, update.scorer, *update.guard);
      update.verdict = guardVerdict(*update.guard, current.has_value(),
                                    "the curated objects, each source of " + std::to_string(folds) +
                                        " left out of the fitting in turn");
    } else {
      update.verdict =
          "unguarded: the curated objects come from one source, so none can be left "
          "out to judge the retrained point decision; it is kept, better or not (a "
          "held-out folder of other sources guards it)";
    }
  }
  update.curatedSets = curated.size();
  update.generatedSets = generated.size();
  return update;
}

fs::path writeScorerUpdate(const ScorerUpdate& update, const fs::path& out) {
  fs::create_directories(out);
  if (update.adopted()) writePointScorer(out, update.adoptedScorer);
  if (!update.adopted() || (update.guard && !update.guard->adoptedWhole())) {
    fs::create_directories(out / "refused");
    writePointScorer(out / "refused", update.scorer);
  }
  if (update.guard)
    writeFileAtomic(out / "scorer_guard.json", toJson(*update.guard).dump(2) + "\n");
  return (update.adopted() ? out : out / "refused") / kPointScorerFile;
}

}  // namespace sagrid
