// `sagrid train`: trains one model (<category>.<type>) on a dataset folder — features through the
// feature pipeline with its cache (default DIR/.sagrid-cache), objects lacking the type skipped
// and counted, the network trained (core/training/trainer.h), point extraction calibrated on the
// training objects, then weights + model card + loss curve (CSV and PNG) written to the output
// folder. Also the default preset: the four shipped models on the generated bench split.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/features/feature_pipeline.h"
#include "core/model/model_card.h"
#include "core/training/trainer.h"

namespace sagrid {

struct DatasetTrainingOptions {
  std::filesystem::path dataDir;
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
  std::size_t objectsUsed = 0;
  std::size_t objectsSkipped = 0;  // of the category, but without an affordance of the type
  std::size_t objectsFailed = 0;   // features could not be computed (logged)
  double featureSeconds = 0;
  double trainingSeconds = 0;
  std::vector<model::EpochRecord> curve;
};

// Throws InvalidArgument for an empty dataset / no object of the category / none with the type.
DatasetTrainingResult trainFromDataset(const DatasetTrainingOptions& options);

// The shipped models, in the order `sagrid train --preset default` trains them.
const std::vector<std::string>& defaultModelNames();

}  // namespace sagrid
