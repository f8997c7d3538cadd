#include "support/tiny_training.h"

namespace sagrid::test {

FeatureOptions tinyFeatures() {
  FeatureOptions f;
  f.resolution = 16;
  f.views = 6;
  return f;
}

DatasetTrainingOptions tinyTraining(const std::string& modelName, const std::filesystem::path& data,
                                    const std::filesystem::path& out, int epochs) {
  DatasetTrainingOptions o;
  o.modelName = modelName;
  o.architecture = kTinyArchitecture;
  o.features = tinyFeatures();
  o.dataDir = data;
  o.outDir = out;
  o.training.epochs = epochs;
  o.training.batchSize = 1;
  return o;
}

}  // namespace sagrid::test
