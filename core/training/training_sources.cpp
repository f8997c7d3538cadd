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

std::vector<TrainingDataSource> defaultTrainingSources(
    const fs::path& benchDir, const std::string& modelName,
    const std::function<void(int, int)>& generateProgress) {
  if (!fs::exists(benchDir / "train" / "manifest.jsonl"))
    gen::generateBenchPreset(benchDir, generateProgress);
  std::vector<TrainingDataSource> sources = {
      {benchDir / "train", 1.0, "data", benchDir / ".sagrid-cache", {}}};
  if (modelName.rfind("sink.", 0) == 0) {
    const auto& wall = gen::wallFixturePreset();
    const fs::path dir = benchDir / wall.front().name;
    if (!fs::exists(dir / "manifest.jsonl")) gen::generatePreset(wall, benchDir, generateProgress);
    sources.push_back({dir, 1.0, "data", benchDir / ".sagrid-cache", {}});
  }
  return sources;
}

std::vector<TrainingDataSource> defaultReplaySources(
    const std::string& modelName, const std::function<void(int, int)>& generateProgress) {
  auto sources = defaultTrainingSources(defaultBenchDir(), modelName, generateProgress);
  double total = 0;
  for (const auto& s : sources) total += s.weight;
  for (auto& s : sources) {
    s.role = "replay";
    s.weight /= total;
  }
  return sources;
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
