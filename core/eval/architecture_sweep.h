// Architecture sweep (the paper's Table I): trains every model for each architecture string on
// DATA/train with the same budget and evaluates it on DATA/val; reports the mean error, training
// time, multiply-accumulates per forward pass and inference time per architecture.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace sagrid {

struct SweepOptions {
  std::filesystem::path dataDir;   // with train/ and val/
  std::filesystem::path outDir;    // models in OUT/sweep/arch<i>/, report OUT/sweep.md + .json
  std::filesystem::path cacheDir;  // default DATA/.sagrid-cache
  std::vector<std::string> architectures;
  std::vector<std::string> modelNames;  // default: the four shipped models
  double minutes = 2;
  int epochs = 0;
  std::string mode = "sparse";
  float nearWeight = 30;  // as the shipped models (train --preset default)
  std::function<void(std::size_t, std::size_t, const std::string&)> onProgress;
};

struct SweepRow {
  std::string id;  // "A1", "A2", ... in the order given
  std::string architecture;
  std::map<std::string, double> errorByModel;  // paper metric (m)
  double meanError = 0;                        // over models (m)
  double trainSeconds = 0;                     // all models
  double forwardGmac = 0;                      // per model forward on a mean-sized val object
  double denseGmac = 0;                        // the same architecture run dense over 64^3
  double modelMilliseconds = 0;                // all models of a category + extraction per object
  std::int64_t parameters = 0;                 // per model
};

struct SweepResult {
  std::vector<SweepRow> rows;  // sorted by mean error, best first (as Table I)
  double meanOccupiedVoxels = 0;
};

std::vector<std::string> splitArchitectures(const std::string& text);  // ';'-separated
SweepResult runArchitectureSweep(const SweepOptions& options);
std::string sweepMarkdown(const SweepResult& result);

}  // namespace sagrid
