// The guard of a point model's fine-tune without a held-out folder (issue 40, item 1: "validated
// on curated objects it did not train on (folds by source)"): the fine-tune is repeated with each
// fold of sources of the curated objects left out (folds disjoint by source: a wild-pool
// repository, a Sweet Home 3D library, else the dataset folder; core/dataset/object_source.h),
// and each fold's candidate and the current model are evaluated with the paper's single-point
// metric on the fold's objects of the model's type. The update is adopted where the candidate's
// error over all folds is lower by more than the standard error of the per-object differences
// (GuardVerdict::pairedNoise); only then is it fine-tuned on every curated object. `sagrid
// train --init ... --guard-by-source` and the GUI's Train panel (no held-out folder) decide here.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>

#include "core/training/dataset_training.h"
#include "core/training/guarded_update.h"

namespace sagrid {

struct PointModelGuardBySource {
  std::filesystem::path currentDir;  // the models folder the update would replace
  // The fine-tune each fold repeats (init, model name, budget, seed, learning rate, features):
  // its datasets of role "data" are the curated objects, left out by source; "replay" datasets
  // train in every fold. Its outDir and command are the caller's; the folds use their own.
  DatasetTrainingOptions fineTune;
  std::filesystem::path workDir;  // the folds' subsets and candidates; removed when done
  int folds = 3;                  // at most the sources of the curated objects of the type
  unsigned seed = 1;              // the folds' assignment of sources
  std::function<void(int fold, int folds)> onFold;  // before each fold's fine-tune
};

// The verdict (GuardVerdict::judgedBySource; currentError and candidateError the means over every
// object judged, pairedNoise the standard error of their per-object differences), or nullopt when
// the curated objects of the model's type come from fewer than two sources: none can be left out
// while another teaches. Throws what training and evaluation throw; InvalidArgument for folds < 2.
std::optional<GuardVerdict> judgeUpdateBySource(const PointModelGuardBySource& guard);

}  // namespace sagrid
