// How far the leave-one-source-out figures of the learned point decision move when its training
// changes a little: the same cross-validation repeated, each time with a share of the generated
// objects left out of training (a different draw each time, whole objects). A decision fitted on a
// few dozen curated objects flips on small changes, so a difference between two designs smaller
// than this spread is not evidence (`sagrid scorer cv --repeats`).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/eval/point_scorer_training.h"

namespace sagrid {

// `sets` without the generated objects of one draw: floor(share x generated objects) of them,
// whole objects (every model's set of a drawn object goes), drawn by `seed` the same on every
// platform; curated objects' sets all stay, in their order. Throws InvalidArgument for a share
// outside [0, 1).
std::vector<CandidateSet> withoutSomeGenerated(const std::vector<CandidateSet>& sets,
                                               double share, unsigned seed);

struct ScorerCvSpread {
  double leftOutShare = 0;
  unsigned firstSeed = 1;  // repeat r draws with firstSeed + r
  // Per repeat, the decision fitted with the curated objects of the other sources: over every
  // fold, and over the folds of sources not tuned on (ScorerCurveOptions::tunedOn).
  std::vector<PointChoiceFigures> all, unseen;
  // Per repeat, every held-out decision (object by object, so runs on other candidate files of
  // the same objects pair repeat by repeat and object by object).
  std::vector<std::vector<HeldOutDecision>> decisions;
};

// `repeats` cross-validations (crossValidatePointScorer, without a learning curve) of `sets`
// with withoutSomeGenerated(sets, share, firstSeed + r).
ScorerCvSpread scorerCvSpread(const std::vector<CandidateSet>& sets,
                              const ScorerTrainingOptions& training,
                              const ScorerCurveOptions& curve, unsigned repeats, double share,
                              unsigned firstSeed);

// A section for scorer_cv.md: each repeat, their mean, standard deviation and range, beside the
// figures of `full` (every generated object in training).
std::string scorerCvSpreadMarkdown(const ScorerCvSpread& spread, const ScorerCrossValidation& full);
nlohmann::json toJson(const ScorerCvSpread& spread);

}  // namespace sagrid
