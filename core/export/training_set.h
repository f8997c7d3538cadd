// "Add to training set": copies an object's mesh and corrected labels into a dataset folder in the
// layout `sagrid train` reads (DIR/<id>/mesh.<ext>, DIR/<id>/labels.json, DIR/manifest.jsonl),
// recording where it came from ("provenance" in labels.json). Re-adding an object replaces it.
#pragma once

#include <filesystem>
#include <string>

#include "core/labels/labels.h"

namespace sagrid {

struct TrainingSetEntry {
  std::string id;
  std::filesystem::path labels;
  std::filesystem::path mesh;
};

// Throws InvalidArgument when the object has no category (training is per category) and
// FileError for unreadable inputs or unwritable outputs. Every file is written atomically; the
// manifest is rewritten last, so an interrupted add leaves the dataset consistent.
TrainingSetEntry addToTrainingSet(const ObjectLabels& labels, const std::filesystem::path& meshPath,
                                  const std::filesystem::path& labelsPath,
                                  const std::filesystem::path& datasetDir);

}  // namespace sagrid
