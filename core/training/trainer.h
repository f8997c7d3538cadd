// Training one SAGrid model on prepared samples (paper, Section III-C): L1 on D(v) over occupied
// voxels, augmentation per step, AdamW with a cosine schedule, fixed seeds, a checkpoint after
// every epoch and resume from it, a loss curve. Plain header; the loop runs in libtorch
// (trainer_torch.cpp, so it shares the torch precompiled header). It lives in core/training, above
// core/model, so dependencies point downward only.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/model/model_card.h"
#include "core/training/augmentation.h"
#include "core/training/training_sample.h"

namespace sagrid::model {

struct TrainingProgress {
  int epoch = 0;  // 1-based, current epoch
  int epochs = 0;
  std::size_t step = 0;   // steps done in total
  std::size_t steps = 0;  // total steps (re-planned before every step when timed)
  double loss = 0;        // running mean loss of the current epoch
  double seconds = 0;     // elapsed
};

struct EpochRecord {
  int epoch = 0;
  double loss = 0;          // mean training loss (L1 on D) over the epoch
  double learningRate = 0;  // at the epoch's end
  double seconds = 0;       // elapsed since the start of training (all sessions)
};

// What a fine-tune changes (issue 40: a few real objects must not undo what the bench taught).
enum class AdaptedPart {
  Everything,  // every weight, batch-norm statistics from the batches (as training from scratch)
  Head,        // the last convolution, its batch norm's scale and shift and the output head; the
               // batch-norm statistics and every earlier layer stay those of the init model
};
const char* toString(AdaptedPart part);           // "everything" | "head"
AdaptedPart parseAdaptedPart(const std::string& text);  // throws InvalidArgument

struct TrainingOptions {
  int epochs = 0;      // 0: from `minutes` (planned anew before every step), else 40
  double minutes = 0;  // time budget of the loop; used only when epochs == 0
  int batchSize = 4;
  double learningRate = 3e-3;
  double weightDecay = 1e-4;
  unsigned seed = 1;
  float targetCap = 0;  // > 0: train on log(1 + min(d, cap)) (see distanceTargets)
  // Beyond the paper: voxels near an instance weigh 1 + nearWeight * exp(-d / nearRadius) in the
  // L1 loss (normalized per object), so the few voxels that decide the argmin are not drowned
  // by the many far ones. 0 = the paper's uniform loss.
  float nearWeight = 0;
  float nearRadius = 0.05f;
  AugmentationRanges augmentation;
  // Mixed data: one sampling weight per sample (core/training/sample_mixing.h). Empty = every
  // sample once per epoch in a shuffled order; else each epoch draws samples.size() samples with
  // replacement in proportion to these weights.
  std::vector<double> sampleWeights;
  std::vector<std::array<int, 3>> vectorChannels;  // rotated with the grid (normals)
  std::filesystem::path checkpointFile;            // written after every epoch; empty = none
  bool resume = false;                             // continue from checkpointFile when it exists
  AdaptedPart adapted = AdaptedPart::Everything;
  std::function<void(const TrainingProgress&)> onProgress;
  const std::atomic<bool>* cancel = nullptr;  // throws Cancelled after saving a checkpoint
};

class AffordanceModel;

// The step count a run with a time budget plans in total once `stepsDone` steps are done, with
// `elapsedSeconds` of `budgetSeconds` spent: as many more as fit at `secondsPerStep` (the pace of
// the current epoch so far), so a machine that gets busy (a GUI drawing beside the run) shortens
// the run instead of stretching it past the budget, and one that gets idle lengthens it. Never
// fewer than `stepsDone`, never fewer than 1.
std::size_t plannedSteps(std::size_t stepsDone, double elapsedSeconds, double secondsPerStep,
                         double budgetSeconds);

// Trains `model` in place on `samples` (each with at least one target). Returns the per-epoch
// loss curve. Throws InvalidArgument for an empty sample list or samples without targets.
std::vector<EpochRecord> trainModel(AffordanceModel& model,
                                    const std::vector<TrainingSample>& samples,
                                    const TrainingOptions& options);

// Mean L1 loss on D over the samples without augmentation (eval mode), for tests and reports.
// `batchStatistics`: normalize with each sample's own batch statistics, as a training step on a
// batch of that one sample does (the running statistics are left unchanged), so a step's loss
// can be compared with it.
double evaluateLoss(AffordanceModel& model, const std::vector<TrainingSample>& samples,
                    float targetCap = 0, bool batchStatistics = false);

}  // namespace sagrid::model
