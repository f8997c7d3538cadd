// `sagrid eval --learning-curve`: its options and run, kept beside eval_command.cpp so the eval
// command only adds them and dispatches. Parsing and progress display only (core/eval).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sagrid::app {

struct LearningCurveCli {
  bool enabled = false;
  std::string init, ks = "0,2,5,10,all", replay, adapt = "everything";
  bool guard = false, keepInit = false;
  std::vector<std::string> models;
  int folds = 3;
  bool bySource = false;
  unsigned seed = 1;
};

// Adds --learning-curve, --init, --model, --folds, --by-source, --ks, --seed, --replay, --adapt, --keep-init, --guard to
// `eval`.
std::shared_ptr<LearningCurveCli> addLearningCurveOptions(CLI::App& eval);

// Runs the learning curve on --data with eval's --minutes / --epochs / --cache / --out when
// --learning-curve was given; returns whether it ran.
bool runLearningCurveIfAsked(const LearningCurveCli& cli, CLI::App& eval, const std::string& data,
                             const std::string& out, const std::string& cache, double minutes,
                             int epochs);

}  // namespace sagrid::app
