#include "support/tiny_training.h"

#include "core/dataset/dataset.h"
#include "core/labels/labels.h"

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

void heatSourcesOnTheKnob(const std::filesystem::path& dir) {
  for (const auto& entry : readDataset(dir)) {
    ObjectLabels labels = readLabels(entry.labels);
    const Eigen::Vector3f knob = labels.ofType("togglebutton").front()->position;
    for (auto& point : labels.affordances)
      if (point.type == "heatsource") point.position = knob;
    writeLabels(entry.labels, labels);
  }
}

}  // namespace sagrid::test
