// Guarded updates (issue 40, DESIGN.md "Updates are guarded"): a model trained or fine-tuned on
// curated objects replaces the current one only where curated objects it did not train on say it
// is better. Both are evaluated with the paper's single-point metric (core/eval) on the held-out
// objects of the model's category and type, paired by object; the candidate is adopted when its
// mean error is lower by more than the standard error of the per-object differences
// (core/common/paired_change.h), else the current model stays and the candidate is kept aside,
// with the figures that refused it.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/common/paired_change.h"
#include "core/features/feature_pipeline.h"

namespace sagrid {

// A model's single-point error on the held-out objects of its type.
struct HeldOutError {
  double error = 0;         // metres (NaN when no object)
  std::size_t objects = 0;
  std::map<std::string, double> byObject;  // each object's error (metres) by its id
};
struct GuardVerdict {
  std::string model;
  std::size_t objects = 0;      // held-out objects of its type evaluated
  double currentError = 0;      // metres (NaN when no object)
  double candidateError = 0;
  bool adopted = false;
  std::string reason;           // one line for the CLI and the GUI
  // Judged by source (core/eval/point_model_guard_by_source.h) instead of on a held-out folder:
  // the curated objects' sources, dealt into `folds` folds each left out of a fine-tune in turn.
  bool judgedBySource = false;
  std::vector<std::string> sources;
  int folds = 0;
  // The standard error of the per-object differences candidate - current (metres; NaN for fewer
  // than two objects); the candidate is adopted only where it is better by more than that.
  double pairedNoise = NAN;
};

// Decides `verdict` from the judged objects' errors (metres) under both models: its objects,
// figures, noise and adoption, and the reason "a cm -> b cm (noise c cm) on WHERE: adopted" (or
// refused, and why).
void decideOnPairedErrors(GuardVerdict& verdict, const std::vector<ObjectFigures>& errors,
                          const std::string& where);

struct GuardOptions {
  std::filesystem::path currentDir;    // the models folder the update would replace
  std::filesystem::path candidateDir;  // where the candidate was trained to
  std::string modelName;               // e.g. "stove.heatsource"
  std::filesystem::path heldOutDir;    // curated objects of other sources than the training data
  std::filesystem::path referenceRoot;  // where heldOutDir's manifest may point
  std::filesystem::path cacheDir;      // features of heldOutDir; empty: heldOutDir/.sagrid-cache
  // The features the models read; unset: from their cards (backend, resolution).
  std::optional<FeatureOptions> features;
};

// Before anything trains: throws ModelError naming the folder when the current models folder
// does not load as one set (models of different versions or feature setups side by side), and
// InvalidArgument listing the curated data's problems (curated_data_check.h) in `trainingDirs`
// and the held-out folder. Nothing is trained then, and the current model stays.
void checkGuardedUpdate(const GuardOptions& options,
                        const std::vector<std::filesystem::path>& trainingDirs);

// The model options.modelName of `modelsDir`, alone, on the held-out objects. Throws what
// evaluation throws (missing model, unreadable data).
HeldOutError heldOutError(const std::filesystem::path& modelsDir, const GuardOptions& options);

// Evaluates both (the current model only when `current` is not given: a caller judging several
// candidates against one current model on one held-out folder evaluates it once; its byObject
// pairs the objects, so a figure without them judges nothing and the current model stays).
GuardVerdict judgeUpdate(const GuardOptions& options,
                         const std::optional<HeldOutError>& current = std::nullopt);

// Puts the verdict into effect in `outDir`: adopted, the candidate's files move there; refused,
// they move to outDir/refused/ (none when the candidate folder is missing: a guard by source
// refuses before the final fine-tune) and the current model's files are copied into outDir
// (unless it is the current folder). Appends the verdict to outDir/guard.jsonl.
void applyVerdict(const GuardVerdict& verdict, const GuardOptions& options,
                  const std::filesystem::path& outDir);

}  // namespace sagrid
