// `sagrid up-axis PATH... [--expect AXIS] [--six] [--cases] [--json]`: which way is up, detected
// from the geometry, and how often that matches a known up axis (the up-axis benchmark).
#include <CLI/CLI.hpp>

#include <iostream>

#include "app/command_registry.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/mesh/mesh_import.h"
#include "core/mesh/up_axis_benchmark.h"

namespace {

void setupUpAxis(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "up-axis", "Detect the up axis (x, -x, y, -y, z, -z) of mesh files from their geometry and, "
                 "where the true axis is known (--expect or labels.json object.up beside the "
                 "mesh), report the accuracy");
  struct Options {
    std::vector<std::string> paths, fitYz;
    std::string expect, weights, weightsOut;
    bool six = false, cases = false, json = false, fit = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("paths", o->paths, "Mesh files or folders")->required();
  cmd->add_option("--expect", o->expect,
                  "The true up axis of files without a labels.json object.up beside them (x, -x, "
                  "y, -y, z, -z; write --expect=-y)")
      ->check([](const std::string& v) {
        return sagrid::parseUpAxis(v) ? std::string() : "must be x, -x, y, -y, z or -z, got " + v;
      });
  cmd->add_flag("--six", o->six, "Also turn every object with a known up axis to all six up directions");
  cmd->add_flag("--cases", o->cases, "One line per object (and direction) with the per-axis scores");
  cmd->add_flag("--json", o->json, "Print the result as JSON");
  cmd->add_option("--fit-yz", o->fitYz,
                  "With --fit: more mesh files or folders, each object turned to +y and +z only "
                  "(the up axes real files come with)");
  cmd->add_flag("--fit", o->fit,
                "Fit the detector's weights on the files with a known up axis and print them "
                "(to paste into core/mesh/up_axis_detection.cpp)");
  cmd->add_option("--weights", o->weights,
                  "Measure the detector with these weights (a file as --fit writes) instead of the "
                  "built-in ones")
      ->check(CLI::ExistingFile);
  cmd->add_option("--weights-out", o->weightsOut,
                  "With --fit: also write the weights to this file");
  cmd->callback([o] {
    sagrid::UpAxisBenchmarkOptions options;
    if (!o->weights.empty()) {
      try {
        options.weights = sagrid::parseUpAxisWeights(sagrid::readFileBytes(o->weights));
      } catch (const sagrid::InvalidArgument& e) {
        throw sagrid::FileError(o->weights, e.what());
      }
    }
    if (!o->expect.empty()) options.expect = sagrid::parseUpAxis(o->expect);
    options.allSix = o->six;
    std::vector<std::filesystem::path> paths(o->paths.begin(), o->paths.end());
    if (o->fit) {
      float accuracy = 0;
      const std::vector<std::filesystem::path> yz(o->fitYz.begin(), o->fitYz.end());
      const auto weights = sagrid::fitUpAxisOnFiles(paths, yz, options, &accuracy);
      std::cout << "training accuracy: " << accuracy << "\nweights: "
                << sagrid::formatUpAxisWeights(weights) << "\n";
      if (!o->weightsOut.empty()) {
        sagrid::writeFileAtomic(o->weightsOut, sagrid::formatUpAxisWeights(weights) + "\n");
      }
      return;
    }
    const auto result = sagrid::benchmarkUpAxis(paths, options);
    if (result.cases.empty() && !result.failures.empty()) {
      throw sagrid::Error(result.failures.front() +
                          (result.failures.size() > 1
                               ? " (and " + std::to_string(result.failures.size() - 1) +
                                     " more files failed)"
                               : ""));
    }
    if (o->json) std::cout << sagrid::upAxisBenchmarkJson(result).dump(2) << "\n";
    else std::cout << sagrid::formatUpAxisBenchmark(result, o->cases);
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("up-axis", setupUpAxis);
