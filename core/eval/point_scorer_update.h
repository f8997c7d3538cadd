// Retraining the learned point decision from curated objects, guarded (issue 40, item 1): the
// candidates of the curated training objects, of generated objects the networks were not trained
// on and of held-out curated objects are made by the models folder's networks as its scorer runs
// them (as `sagrid scorer candidates`); a scorer fitted on the first two replaces the folder's
// decisions where the guard judges it better on the held-out objects, each category's mixes of
// the two judged as a whole (guardPointScorer, adoptedScorer). The GUI's Train panel
// ("Retrain point decision") goes through here; `sagrid scorer candidates` + `scorer train
// --guard` do the same in steps.
#pragma once

#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/eval/point_scorer_training.h"

namespace sagrid {

struct ScorerUpdateRequest {
  std::filesystem::path models;     // networks that make the candidates; its scorer is the current one
  std::filesystem::path curated;    // the curated training objects (a dataset)
  // Generated objects (a dataset; its val/ split when it has one). Empty: those the shipped
  // decision learned from, none of which the networks were trained on: the bench's val split and
  // its decision split (defaultBenchDir(), gen::decisionPreset()), each generated once when
  // missing.
  std::filesystem::path generated;
  // Curated objects of other sources: the guard's; empty: the curated objects judge, each source
  // left out in turn (guardPointScorerBySource), unguarded when they are of one source.
  std::filesystem::path heldOut;
  ScorerTrainingOptions training;
  // Per object while candidates are made: the phase ("curated", "generated", "held out"; "bench"
  // while the bench is generated), done, total and the object.
  std::function<void(const std::string&, std::size_t, std::size_t, const std::string&)> onProgress;
  const std::atomic<bool>* cancel = nullptr;  // set: Cancelled is thrown between objects
};

// The generated objects the shipped decision learned from, under `benchDir`: its val split and
// its decision split (gen::decisionPreset()), each generated first where its manifest is missing
// (`progress` per object generated).
std::vector<std::filesystem::path> decisionGeneratedDirs(
    const std::filesystem::path& benchDir, const std::function<void(int, int)>& progress = {});

struct ScorerUpdate {
  PointScorer scorer;                // the freshly fitted one, adopted or not
  // What the models folder gets: the fresh decisions of the models the guard adopted beside the
  // current ones of the others (adoptedScorer); unguarded, the fresh one.
  PointScorer adoptedScorer;
  std::optional<ScorerGuard> guard;  // with a held-out folder, or judged by source
  std::size_t curatedSets = 0, generatedSets = 0, heldOutSets = 0;
  std::string verdict;               // one line: the edits before and after, and the decision
  // For at least one model; unguarded: always.
  bool adopted() const { return !guard || guard->adopted; }
};

// The guard without held-out objects (issue 40: folds by source). Each source of the curated
// sets of `training` (the generated ones always train) is decided by a decision fitted with
// `options` on the other sets, and by `current` as it is (none: the count's points; should it
// have been fitted on some of these objects, the comparison favours it), each fold judged as
// guardPointScorer judges a held-out folder and each model's edits summed over the folds. Every
// fold has its own new decision, so no one mix of a category's decisions is judged: a category's
// new decisions are adopted together where its objects' edits, paired over the folds, are fewer
// by more than the standard error of their differences (core/common/paired_change.h), else none.
// nullopt for curated sets of fewer than two sources (none can be left out while another
// teaches). `onFold(k, folds)` before each fold's fitting.
std::optional<ScorerGuard> guardPointScorerBySource(
    const PointScorer* current, const std::vector<const CandidateSet*>& training,
    const ScorerTrainingOptions& options, const std::function<void(int, int)>& onFold = {});

// Throws InvalidArgument when the curated objects give no candidate set with ground truth, or
// as guardPointScorer does (a held-out object also in training); FileError for unreadable data.
ScorerUpdate updatePointScorer(const ScorerUpdateRequest& request);

// `fresh` judged against `current` (none: the count's points) on the held-out candidates
// (guardPointScorer; none: unguarded, adopted), with the one-line verdict. `sagrid scorer train
// --guard` and updatePointScorer both decide here.
ScorerUpdate judgeScorerUpdate(PointScorer fresh, const std::optional<PointScorer>& current,
                               const std::vector<CandidateSet>& heldOut,
                               const std::vector<const CandidateSet*>& training);

// Writes `update` into the models folder `out`: the adopted scorer as point_scorer.json there when
// any model adopted, and the fresh one in out/refused/ when some model refused it (out keeps what
// it had where nothing was adopted); the guard's figures per model in out/scorer_guard.json.
// Returns the scorer file written into `out` (or, where nothing was adopted, out/refused's).
std::filesystem::path writeScorerUpdate(const ScorerUpdate& update, const std::filesystem::path& out);

}  // namespace sagrid
