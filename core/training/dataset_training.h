// `sagrid train`: trains one model (<category>.<type>) on a dataset folder — features through the
// feature pipeline with its cache (default DIR/.sagrid-cache), objects lacking the type skipped
// and counted, the network trained (core/training/trainer.h), point extraction calibrated on the
// training objects, then weights + model card + loss curve (CSV and PNG) written to the output
// folder. Also the default preset: the four shipped models on the generated bench split.
// Fine-tuning: several datasets drawn by weight (new data beside a replay of the bench split),
// starting from an existing model's weights (`init`).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/features/feature_pipeline.h"
#include "core/model/model_card.h"
#include "core/training/trainer.h"
#include "core/training/training_sources.h"

namespace sagrid {

// Peak learning rates of the cosine schedule. Fine-tuning starts from weights that already sit in
// a good basin; 1e-3 is the rate the from-scratch schedule (peak 3e-3) passes about 60 % into its
// run, past the large-step phase, so the first steps on a few new objects nudge the shipped
// weights instead of undoing what the bench split taught them. (Chosen, not swept.)
inline constexpr double kFromScratchLearningRate = 3e-3;
inline constexpr double kFineTuneLearningRate = 1e-3;

// Fewer training objects than this: a fine-tune keeps the init model's point-extraction
// calibration (a grid search of 63 settings over a handful of objects is noise).
inline constexpr std::size_t kMinCalibrationObjects = 10;

struct DatasetTrainingOptions {
  std::filesystem::path dataDir;  // one dataset of weight 1; used when `datasets` is empty
  // Mixed data: each dataset's objects of the model's category with the type, drawn per step by
  // dataset weight, then uniformly within the dataset; an epoch is as many samples as all
  // datasets hold together. Each needs at least one object of the category (InvalidArgument).
  std::vector<TrainingDataSource> datasets;
  // Start from this model (card, .pt or a folder with <modelName>.json). Architecture (when
  // `architecture` is empty it is the init's), mode, feature backend, config, channel counts and
  // grid must match (ModelError naming both). A checkpoint with `training.resume` wins over it.
  std::filesystem::path init;
  // With `init`: train with the init card's loss settings (near weight and radius, target cap)
  // instead of those in `training`, so the fine-tune optimizes what the model was trained for.
  bool lossFromInit = true;
  // With `init`: the result keeps the init model's networks and adds the fine-tuned one beside
  // them (core/model/model_ensemble.h keepInitNetworks: the mean of their fields, the init's card
  // and point extraction, an earlier such fine-tune's network replaced), so what the init knew
  // stays in every prediction (`train --keep-init`).
  bool keepInitNetworks = false;
  // The card's point_extraction.coarse_to_fine (annotate's second pass for this model); unset:
  // the init card's, false without one.
  std::optional<bool> coarseToFine;
  // The card's point_extraction.crease_patches (the learned decision's candidates on crease
  // patches for this model); unset: the init card's, false without one.
  std::optional<bool> creasePatches;
  std::string modelName;     // "<category>.<type>"
  std::string architecture;  // empty = kDefaultArchitecture
  std::string mode = "sparse";
  model::TrainingOptions training;  // epochs / minutes / seed / batch size / resume ...
  FeatureOptions features;          // cacheDir empty = dataDir/.sagrid-cache
  std::filesystem::path outDir;     // card: outDir/<name>.json
  std::string command;              // the command line, recorded in the card
  // Feature extraction progress (done, total, object id).
  std::function<void(std::size_t, std::size_t, const std::string&)> onFeatureProgress;
};

struct DatasetTrainingResult {
  std::filesystem::path cardFile;
  model::ModelCard card;
  std::size_t objectsUsed = 0;     // over all datasets
  std::size_t objectsSkipped = 0;  // of the category, but without an affordance of the type
  std::size_t objectsFailed = 0;   // features could not be computed (logged)
  double featureSeconds = 0;
  double trainingSeconds = 0;
  std::vector<model::EpochRecord> curve;
  bool recalibrated = true;  // false: point extraction kept from the init model
};

// Throws InvalidArgument for an empty dataset / no object of the category / none with the type,
// ModelError for an init model that does not match.
DatasetTrainingResult trainFromDataset(const DatasetTrainingOptions& options);

// The shipped models, in the order `sagrid train --preset default` trains them.
const std::vector<std::string>& defaultModelNames();

}  // namespace sagrid
