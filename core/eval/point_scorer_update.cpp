#include "core/eval/point_scorer_update.h"

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

}  // namespace

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
  update.verdict = std::to_string(guard.currentEdits) + " -> " + std::to_string(guard.newEdits) +
                   " edits on the held-out objects (" +
                   (current ? "the current point decision" : "the count's points") +
                   " -> the retrained one): " +
                   (!guard.adopted         ? "refused, the current decision stays"
                    : guard.adoptedWhole() ? "adopted"
                                           : "adopted where better (" +
                                                 std::to_string(guard.adoptedEdits) +
                                                 " edits); kept the decision before for " +
                                                 modelsWhere(guard, false));
  return update;
}

ScorerUpdate updatePointScorer(const ScorerUpdateRequest& request) {
  // Every folder before any candidate is made (minutes of work).
  for (const fs::path& dir : {request.curated, request.generated, request.heldOut})
    if (!dir.empty() && !fs::is_directory(dir)) throw FileError(dir, "dataset folder not found");
  fs::path generatedDir = request.generated;
  if (generatedDir.empty()) {
    generatedDir = defaultBenchDir();
    if (!fs::exists(generatedDir / "val" / "manifest.jsonl"))
      gen::generateBenchPreset(generatedDir, [&](int done, int total) {
        if (request.onProgress) request.onProgress("bench", done, total, "");
      });
  }
  const ModelSet models = ModelSet::load(request.models);
  const auto curated = candidatesOf(models, request.curated, "curated", request);
  if (withTruth(curated) == 0)
    throw InvalidArgument("the curated objects of " + request.curated.string() +
                          " give the point decision nothing to learn: no object with points of "
                          "a model in " + request.models.string());
  const auto generated = candidatesOf(models, generatedDir, "generated", request);
  std::vector<const CandidateSet*> training;
  for (const auto& s : curated) training.push_back(&s);
  for (const auto& s : generated) training.push_back(&s);
  const auto heldOut = request.heldOut.empty()
                           ? std::vector<CandidateSet>{}
                           : candidatesOf(models, request.heldOut, "held out", request);
  ScorerUpdate update = judgeScorerUpdate(trainPointScorer(training, request.training),
                                          readPointScorer(request.models), heldOut, training);
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
