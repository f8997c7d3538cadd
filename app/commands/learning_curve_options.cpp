#include "app/commands/learning_curve_options.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/common/error.h"
#include "core/common/resource_paths.h"
#include "core/eval/learning_curve.h"

namespace sagrid::app {
namespace fs = std::filesystem;

std::shared_ptr<LearningCurveCli> addLearningCurveOptions(CLI::App& eval) {
  auto o = std::make_shared<LearningCurveCli>();
  eval.add_flag("--learning-curve", o->enabled,
                "k-fold over DATA's objects: fine-tune --init on k objects of the training folds "
                "(with the bench replay, as `sagrid train --init`) and measure the paper error on "
                "the held-out fold; OUT/learning_curve.md, .json, .png. --minutes / --epochs are "
                "per fine-tune (default 5 epochs)");
  eval.add_option("--init", o->init,
                  "With --learning-curve: the models to fine-tune (default resources/models)");
  eval.add_option("--model", o->models,
                  "With --learning-curve: models to fine-tune (repeatable; default every init "
                  "model with objects in DATA)");
  eval.add_option("--folds", o->folds, "With --learning-curve: folds (default 3)")
      ->check(CLI::Range(2, 1000));
  eval.add_flag("--by-source", o->bySource,
                "With --learning-curve: folds of whole sources (each wild-pool repository, Sweet "
                "Home 3D library, other dataset folder), none fine-tuned on and held out at once "
                "(leave-one-source-out); --folds is then the number of source groups");
  eval.add_option("--ks", o->ks,
                  "With --learning-curve: object counts, e.g. 0,2,5,10,all (default)");
  eval.add_option("--seed", o->seed, "With --learning-curve: seed of the folds and fine-tunes");
  eval.add_option("--adapt", o->adapt,
                  "With --learning-curve: what each fine-tune changes: everything (default) or "
                  "head (the last layer and the output head; batch-norm statistics kept)")
      ->check(CLI::IsMember({"everything", "head"}));
  eval.add_flag("--keep-init", o->keepInit,
                "With --learning-curve: each fine-tune keeps the init model's networks beside "
                "the fine-tuned one, as `train --keep-init` does");
  eval.add_flag("--guard", o->guard,
                "With --learning-curve: guard every fine-tune as `train --guard` does, on a "
                "quarter of the training folds' sources held out of the fine-tunes; where the "
                "guard refuses, the init model stands for that k");
  eval.add_option("--replay", o->replay,
                  "With --learning-curve: replay folder (default the bench split's train half); "
                  "none = no replay");
  return o;
}

bool runLearningCurveIfAsked(const LearningCurveCli& cli, CLI::App& eval, const std::string& data,
                             const std::string& out, const std::string& cache, double minutes,
                             int epochs) {
  if (!cli.enabled) return false;
  LearningCurveOptions o;
  o.dataDir = data;
  o.initDir = !cli.init.empty() ? fs::path(cli.init) : sagrid::defaultModelsDir();
  o.modelNames = cli.models;
  o.folds = cli.folds;
  o.bySource = cli.bySource;
  o.ks = parseLearningCurveKs(cli.ks);
  o.seed = cli.seed;
  o.epochs = epochs;
  o.minutes = eval.count("--minutes") ? minutes : 0;  // eval's --minutes default is --sweep's
  o.replay = cli.replay != "none";
  o.adapted = sagrid::model::parseAdaptedPart(cli.adapt);
  o.guarded = cli.guard;
  o.keepInitNetworks = cli.keepInit;
  if (o.replay && !cli.replay.empty()) o.replayDir = cli.replay;
  o.cacheDir = cache;
  o.outDir = out;
  o.onMessage = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  const LearningCurveReport report = runLearningCurve(o);
  writeLearningCurveReport(report, out);
  std::cout << learningCurveMarkdown(report);
  std::fprintf(stderr, "learning curve: %s/learning_curve.md, .json, .png\n", out.c_str());
  return true;
}

}  // namespace sagrid::app
