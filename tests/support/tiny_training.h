// Tiny training setups for tests of the training machinery, not of accuracy: a 16^3 grid with 6
// views and a two-layer network train on a few generated objects in about a second.
#pragma once

#include <filesystem>
#include <string>

#include "core/features/feature_pipeline.h"
#include "core/training/dataset_training.h"

namespace sagrid::test {

inline constexpr const char* kTinyArchitecture = "[3,1,8],[3,2,8,2]";

FeatureOptions tinyFeatures();

// `modelName` trained on `data` into `out` with tinyFeatures() and kTinyArchitecture, batch 1.
DatasetTrainingOptions tinyTraining(const std::string& modelName, const std::filesystem::path& data,
                                    const std::filesystem::path& out, int epochs = 1);

// Every heat source of `dir`'s objects moved onto the object's first knob: a labelling convention
// a model trained on it learns and others do not.
void heatSourcesOnTheKnob(const std::filesystem::path& dir);

}  // namespace sagrid::test
