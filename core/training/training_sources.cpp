#include "core/training/training_sources.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/dataset/dataset.h"
#include "core/generate/dataset_generator.h"

namespace sagrid {
namespace fs = std::filesystem;

TrainingDataSource parseTrainingDataSource(const std::string& argument, const std::string& role) {
  TrainingDataSource source;
  source.role = role;
  source.dir = argument;
  const auto colon = argument.rfind(':');
  if (colon != std::string::npos && colon > 0 && colon + 1 < argument.size()) {
    const std::string suffix = argument.substr(colon + 1);
    char* end = nullptr;
    const double w = std::strtod(suffix.c_str(), &end);
    if (end && *end == '\0') {
      if (!(w > 0))
        throw InvalidArgument("dataset " + argument.substr(0, colon) + ": sampling weight " +
                              suffix + " must be a positive number");
      source.dir = argument.substr(0, colon);
      source.weight = w;
    }
  }
  if (source.dir.empty()) throw InvalidArgument("empty dataset path in \"" + argument + "\"");
  return source;
}

fs::path defaultBenchDir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return fs::path(xdg) / "sagrid" / "bench";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "sagrid" / "bench";
  return fs::path(".sagrid-data") / "bench";
}

TrainingDataSource defaultReplaySource(const std::function<void(int, int)>& generateProgress) {
  const fs::path bench = defaultBenchDir();
  if (!fs::exists(bench / "train" / "manifest.jsonl"))
    gen::generateBenchPreset(bench, generateProgress);
  TrainingDataSource source;
  source.dir = bench / "train";
  source.role = "replay";
  source.cacheDir = bench / ".sagrid-cache";  // the preset's cache, shared by both splits
  return source;
}

fs::path resolveInitCard(const fs::path& init, const std::string& modelName) {
  fs::path card = init;
  if (fs::is_directory(init))
    card = init / (modelName + ".json");
  else if (init.extension() == ".pt")
    card = fs::path(init).replace_extension(".json");
  if (!fs::is_regular_file(card))
    throw FileError(card, fs::is_directory(init)
                              ? "--init folder has no model card for " + modelName
                              : "--init: model card not found (expected beside the weights)");
  return card;
}

DatasetFingerprint datasetFingerprint(const fs::path& dir) {
  if (fs::is_regular_file(dir / "manifest.jsonl"))
    return {sha256Hex(readFileBytes(dir / "manifest.jsonl")), "manifest.jsonl"};
  std::vector<std::string> lines;
  for (const auto& entry : readDataset(dir))
    lines.push_back(entry.labels.lexically_relative(dir).generic_string() + " " +
                    sha256Hex(readFileBytes(entry.labels)) + "\n");
  std::sort(lines.begin(), lines.end());
  std::string all;
  for (const auto& l : lines) all += l;
  return {sha256Hex(all), "labels.json files"};
}

}  // namespace sagrid
