// Where training data and starting weights come from when a model is fine-tuned: dataset folders
// with sampling weights ("DIR:w"), the replay of the generated bench split beside new data, the
// init model (a card or a folder of shipped models), and a fingerprint of each dataset for the
// model card. Shared by `sagrid train`, `sagrid eval --learning-curve` and the GUI's Train panel.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sagrid {

struct TrainingDataSource {
  std::filesystem::path dir;
  double weight = 1;          // relative sampling weight (sample_mixing.h)
  std::string role = "data";  // "data" (what the model is trained or fine-tuned on) or "replay"
  std::filesystem::path cacheDir;  // feature cache; empty = dir/.sagrid-cache
  // Where dir's manifest may point (readDataset); empty: inside dir only.
  std::filesystem::path referenceRoot;
};

// "DIR" or "DIR:w" (w a positive number) -> source with that weight. A suffix after the last ':'
// that is not a number belongs to the path. Throws InvalidArgument for w <= 0.
TrainingDataSource parseTrainingDataSource(const std::string& argument,
                                           const std::string& role = "data");

// The bench split root `sagrid train --preset default` uses: $XDG_CACHE_HOME/sagrid/bench, else
// ~/.cache/sagrid/bench, else .sagrid-data/bench.
std::filesystem::path defaultBenchDir();

// What `sagrid train --preset default` trains `modelName` on, under `benchDir` (generated there
// when missing, all sharing benchDir/.sagrid-cache): the bench split's train half, and for the
// sink models also the sinks with wall fixtures (gen::wallFixturePreset(), weight 1).
std::vector<TrainingDataSource> defaultTrainingSources(
    const std::filesystem::path& benchDir, const std::string& modelName,
    const std::function<void(int done, int total)>& generateProgress = {});

// The default replay for fine-tuning `modelName`: what `--preset default` trains it on
// (defaultTrainingSources under defaultBenchDir(), generated when missing), role "replay", the
// weights scaled to sum to 1 so the caller sets the replay's share with one factor.
std::vector<TrainingDataSource> defaultReplaySources(
    const std::string& modelName,
    const std::function<void(int done, int total)>& generateProgress = {});

// --init: a card or weights file (MODEL.json / MODEL.pt) or a folder holding <modelName>.json.
// Returns the card path; throws FileError when it is missing.
std::filesystem::path resolveInitCard(const std::filesystem::path& init,
                                      const std::string& modelName);

struct DatasetFingerprint {
  std::string sha256;
  std::string of;  // "manifest.jsonl" or "labels.json files" (what the hash covers)
};

// The sha256 of DIR/manifest.jsonl when there is one; else the sha256 of the sorted lines
// "<labels path relative to DIR> <sha256 of its bytes>\n" over the dataset's labels files.
DatasetFingerprint datasetFingerprint(const std::filesystem::path& dir);

}  // namespace sagrid
