// Measuring up-axis detection on mesh files whose up axis is known (from --expect or the
// object.up of a labels.json beside the mesh), optionally with every object also turned to all
// six up directions, so `sagrid up-axis` can report accuracy per set and be re-run.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/mesh/up_axis_detection.h"

namespace sagrid {

struct UpAxisCase {
  std::string id;                   // object id, with "@<axis>" when turned (all six)
  std::optional<UpAxis> expected;   // unknown: reported, not counted
  UpAxisDetection detection;
};

struct UpAxisBenchmark {
  std::vector<UpAxisCase> cases;
  std::vector<std::string> failures;  // "path: why" for files that could not be imported

  int counted() const;  // cases with a known expected axis
  int correct() const;
};

struct UpAxisBenchmarkOptions {
  std::optional<UpAxis> expect;  // the up axis of files without a labels.json object.up
  bool allSix = false;           // also turn each object (known up) to all six up directions
  UpAxisWeights weights = defaultUpAxisWeights();  // the detector measured
  std::function<void(std::size_t done, std::size_t total, const std::string& id)> onProgress;
};

// `paths`: mesh files or folders (searched like findMeshFiles). Import problems are recorded in
// `failures`, not thrown.
UpAxisBenchmark benchmarkUpAxis(const std::vector<std::filesystem::path>& paths,
                                const UpAxisBenchmarkOptions& options);

// Fits the detector's weights on the files with a known up axis: each object of `paths` turned
// to all six up directions (options.allSix) or to +y and +z (as real files come), and each object
// of `yzPaths` to +y and +z. Returns them with the training accuracy.
UpAxisWeights fitUpAxisOnFiles(const std::vector<std::filesystem::path>& paths,
                               const std::vector<std::filesystem::path>& yzPaths,
                               const UpAxisBenchmarkOptions& options, float* accuracy);
// The weights as a C++ initializer, to paste into defaultUpAxisWeights(), and back (a file of
// them measured with `sagrid up-axis --weights` before pasting). Throws InvalidArgument naming
// what is wrong when the text is not kUpAxisParameterCount finite numbers.
std::string formatUpAxisWeights(const UpAxisWeights& weights);
UpAxisWeights parseUpAxisWeights(const std::string& text);

// A table: one line per case (id, expected, detected, confidence, per-axis scores) and totals
// (accuracy, 6x6 confusion, mean confidence of right and wrong choices).
std::string formatUpAxisBenchmark(const UpAxisBenchmark& benchmark, bool perCase);
nlohmann::json upAxisBenchmarkJson(const UpAxisBenchmark& benchmark);

}  // namespace sagrid
