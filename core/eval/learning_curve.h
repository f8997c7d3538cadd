// `sagrid eval --learning-curve`: how much fine-tuning on k real objects helps. k-fold over the
// real dataset's objects (seeded, folds disjoint); for each fold and each k the init models are
// fine-tuned (with the bench replay, exactly as `sagrid train --init` does) on k objects of the
// training folds (k = 0: the init models unchanged) and evaluated with the paper's single-point
// metric (core/eval) on the held-out fold. Reports error vs k with the spread across folds as
// Markdown, JSON and a PNG.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/training/trainer.h"
#include "core/training/training_sources.h"

namespace sagrid {

inline constexpr int kAllObjects = -1;  // "all" in --ks: every training-fold object

struct LearningCurveOptions {
  std::filesystem::path dataDir;  // the real dataset (object folders or manifest.jsonl)
  std::filesystem::path initDir;  // the models fine-tuned, evaluated as they are for k = 0
  std::vector<std::string> modelNames;  // empty = every model of initDir with data objects
  int folds = 3;                        // clamped to the object count (by source: the sources)
  // Folds of whole sources (core/dataset/object_source.h: a repository, a library, a dataset
  // folder): no source is both fine-tuned on and held out, the leave-one-source-out protocol.
  bool bySource = false;
  std::vector<int> ks = {0, 2, 5, 10, kAllObjects};
  unsigned seed = 1;
  int epochs = 0;       // per fine-tune; 0 = `minutes`
  double minutes = 0;   // per fine-tune; both 0 = 5 epochs
  bool replay = true;   // replay beside the k objects (weighted 1:1)
  model::AdaptedPart adapted = model::AdaptedPart::Everything;  // what each fine-tune changes
  // Each fine-tune keeps the init model's networks beside the fine-tuned one (`train --keep-init`).
  bool keepInitNetworks = false;
  // Each fine-tune guarded as `train --guard` guards it (core/training/guarded_update.h): a
  // quarter of the training folds' sources (at least one, seeded) is the guard set and the k
  // objects come from the rest; the fine-tuned model is kept only where its error on the guard
  // set is lower than the init model's, else the init model stands for that k.
  bool guarded = false;
  std::filesystem::path replayDir;  // empty = the default bench replay (training_sources.h)
  std::filesystem::path cacheDir;   // features of dataDir; empty = dataDir/.sagrid-cache
  std::filesystem::path outDir;     // report; fine-tuned models under outDir/work/
  std::function<void(const std::string&)> onMessage;  // one line per fine-tune and evaluation
};

struct LearningCurvePoint {
  std::string model;
  int fold = 0;        // 1-based
  int k = 0;           // requested (kAllObjects for "all")
  int kUsed = 0;       // objects of the model's type actually fine-tuned on
  std::size_t testObjects = 0;  // held-out objects evaluated for this model
  double paperError = 0;        // metres, mean over testObjects; NaN when none
  bool adopted = true;          // guarded: the fine-tune passed the guard (k = 0: true)
};

struct LearningCurveReport {
  std::filesystem::path dataDir, initDir;
  unsigned seed = 1;
  std::vector<std::vector<std::string>> folds;  // object ids per fold
  std::vector<std::vector<std::string>> foldSources;  // by source: the sources of each fold
  std::vector<int> ks;
  std::vector<std::string> modelNames;
  std::vector<LearningCurvePoint> points;
  bool replay = true;
  model::AdaptedPart adapted = model::AdaptedPart::Everything;
  bool keepInitNetworks = false;
  bool guarded = false;
  int epochs = 0;
  double minutes = 0;
};

// Object indices 0..count-1 in `folds` disjoint folds covering each once (sizes differ by at most
// one), from a seeded shuffle. With `groups` (one label per object, e.g. its category) the folds
// are stratified: each group is shuffled and dealt over the folds in turn, so every fold holds
// its share of every group (a fold of sinks only would measure the stove models on nothing).
// Throws InvalidArgument for count < 2, folds < 2 or groups of another size.
std::vector<std::vector<std::size_t>> kFoldSplit(std::size_t count, int folds, unsigned seed,
                                                 const std::vector<std::string>& groups = {});

// Object indices in `folds` disjoint folds of whole sources (sources[i] is object i's): the
// sources in a seeded order, largest first, each dealt to the fold with the fewest objects so far.
// The same seed gives the same folds. Throws InvalidArgument for fewer than 2 sources or folds.
std::vector<std::vector<std::size_t>> sourceFoldSplit(const std::vector<std::string>& sources,
                                                      int folds, unsigned seed);

// "0,2,5,10,all" -> {0, 2, 5, 10, kAllObjects}; throws InvalidArgument for anything else.
std::vector<int> parseLearningCurveKs(const std::string& text);

LearningCurveReport runLearningCurve(const LearningCurveOptions& options);

std::string learningCurveMarkdown(const LearningCurveReport& report);
nlohmann::json learningCurveJson(const LearningCurveReport& report);
// learning_curve.md, .json and .png (mean error vs k per model, +-1 standard deviation across
// folds as thin lines) in `outDir`.
void writeLearningCurveReport(const LearningCurveReport& report,
                              const std::filesystem::path& outDir);

}  // namespace sagrid
