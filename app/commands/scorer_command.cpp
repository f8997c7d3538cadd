// `sagrid scorer`: the learned point decision (core/annotate/point_scorer.h). `candidates` runs
// the models over labelled data and saves every model's point candidates with the ground truth;
// `cv` measures the decision leave one source out on them; `train` fits it and writes a models
// folder with point_scorer.json. Parsing and progress display only.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "app/command_registry.h"
#include "app/commands/pass_options_flags.h"
#include "app/progress_bar.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/resource_paths.h"
#include "core/eval/evaluation.h"
#include "core/eval/point_scorer_training.h"
#include "core/eval/scorer_cv_pairing.h"
#include "core/eval/scorer_cv_spread.h"
#include "core/eval/scorer_learning_curve_plot.h"
#include "core/eval/point_scorer_update.h"
#include "core/model/model_card.h"
#include "core/model/model_files.h"

namespace {
namespace fs = std::filesystem;

std::vector<sagrid::CandidateSet> readAll(const std::vector<std::string>& files) {
  std::vector<sagrid::CandidateSet> all;
  for (const auto& file : files) {
    auto sets = sagrid::readCandidateSets(file);
    all.insert(all.end(), std::make_move_iterator(sets.begin()), std::make_move_iterator(sets.end()));
  }
  return all;
}

// A models folder `out` with the fitted scorer where its verdict says (`from`'s files copied first
// unless it is `from`), the figures per model and the verdict reported; returns the scorer file.
fs::path writeModelsWithScorer(const fs::path& from, const fs::path& out,
                               const sagrid::ScorerUpdate& update) {
  std::error_code same;
  if (!(fs::exists(out) && fs::equivalent(from, out, same))) sagrid::model::copyModelFiles(from, out);
  const fs::path file = sagrid::writeScorerUpdate(update, out);
  if (update.guard)
    for (const auto& v : update.guard->byModel)
      std::fprintf(stderr, "guard: %s\n", sagrid::toString(v).c_str());
  std::fprintf(stderr, "scorer: %zu models, trained on %s; %s -> %s\n",
               update.scorer.byModel.size(), update.scorer.trainedOn.c_str(),
               update.verdict.c_str(), file.c_str());
  return file;
}

// A decision learned from (or judged on) candidates of other networks than `models`' would decide
// on fields it never saw: refused before training, naming the object, the model and what to run.
// Candidate files written before the weights were recorded pass.
void refuseOtherWeights(const std::vector<sagrid::CandidateSet>& sets, const fs::path& models) {
  const std::map<std::string, std::string> cardWeights = sagrid::model::cardWeights(models);
  for (const auto& set : sets) {
    const auto card = cardWeights.find(set.model);
    if (set.networkWeights.empty() || card == cardWeights.end() || set.networkWeights == card->second)
      continue;
    throw sagrid::InvalidArgument(
        "the candidates of " + set.model + " on " + set.object + " were made by other weights (" +
        set.networkWeights.substr(0, 8) + ") than its card in " + models.string() + " (" +
        card->second.substr(0, 8) + "): make them again with `sagrid scorer candidates --models " +
        models.string() + "`");
  }
}

// The options `cv` and `train` share: the candidate files and how the decision is fitted.
void addTrainingOptions(CLI::App& cmd, std::vector<std::string>& candidates,
                        sagrid::ScorerTrainingOptions& o) {
  cmd.add_option("--candidates", candidates, "Candidate files (repeatable)")->required();
  cmd.add_option("--real-weight", o.realWeight,
                 "Weight of a curated real object's candidates against a generated object's "
                 "(default 3)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--ridge", o.ridge, "Ridge on the classifier's weights (default 1)")
      ->check(CLI::NonNegativeNumber);
  cmd.add_flag_callback("--logistic", [&o] { o.trees = false; },
                        "A ridge logistic regression instead of boosted trees");
  cmd.add_flag_callback("--no-context", [&o] { o.context = false; },
                        "Trees without the second look in the company of the object's other "
                        "candidates (repeated parts, rows)");
  cmd.add_flag_callback(
      "--no-copies", [&o] { o.copyThresholds = {sagrid::PointChoice{}.copyThreshold}; },
      "A chosen point never brings its places on its part's copies");
  cmd.add_flag_callback("--least-cost-choice", [&o] { o.smoothChoice = false; },
                        "The choice of thresholds with the least training edits alone (before "
                        "session 44), instead of the one whose neighbours' edits are least too");
  cmd.add_flag_callback("--no-learned-count", [&o] { o.learnedCount = false; },
                        "No learned count of points: the choice's thresholds alone decide how "
                        "many (before session 46)");
  cmd.add_flag_callback(
      "--no-other-models-count", [&o] { o.otherModelsCount = false; },
      "The learned count reads its own model's candidates alone, not the "
      "object's other models of the category (before session 47)");
  cmd.add_flag("--skip-unreached", o.skipUnreached,
               "Leave out of training an object's candidates of a model whose true points no "
               "candidate reaches (every candidate a non-point)");
  cmd.add_option("--rounds", o.boosting.rounds, "Boosting rounds (default 100)");
  cmd.add_option("--depth", o.boosting.depth, "Tree depth (default 3)");
  cmd.add_option("--min-leaf-hessian", o.boosting.minLeafHessian,
                 "Least weighted p(1 - p) a tree's leaf holds (default 1)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--leaf-ridge", o.boosting.lambda, "Ridge on the trees' leaf values (default 1)")
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--row-share", o.boosting.rowShare,
                 "Share of the candidates each tree is grown on, drawn per tree (stochastic "
                 "boosting; default 1, all)")
      ->check(CLI::Range(0.01, 1.0));
  cmd.add_option("--feature-share", o.boosting.featureShare,
                 "Share of the features each tree may split on, drawn per tree (default 0.5)")
      ->check(CLI::Range(0.01, 1.0));
}

void setupScorer(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "scorer",
      "The learned point decision: a classifier per model over point candidates (the passes' "
      "points, the field's minima, the mesh's small parts) that chooses which are affordance "
      "points and how many. `candidates` saves them from labelled data, `cv` measures the "
      "decision leave one source out, `train` writes it into a models folder (point_scorer.json)");
  cmd->require_subcommand(1);

  struct CandidatesOptions {
    std::vector<std::string> data;
    std::string models, out, cache;
    sagrid::PassOptions passes;
  };
  auto c = std::make_shared<CandidatesOptions>();
  auto* candidates = cmd->add_subcommand(
      "candidates", "Run the models over labelled data (as `sagrid eval`, passes included) and "
                    "save every model's point candidates with the ground truth to --out (JSON)");
  candidates->add_option("--data", c->data, "Labelled dataset (repeatable; its val/ split when "
                                            "it has one)")->required();
  candidates->add_option("--models", c->models, "Model folder (default resources/models)");
  candidates->add_option("--out", c->out, "Candidate file to write")->required();
  candidates->add_option("--cache", c->cache, "Feature cache (default DATA/.sagrid-cache)");
  sagrid::app::addPassOptions(*candidates, c->passes);
  candidates->callback([c] {
    const fs::path modelsDir = c->models.empty() ? sagrid::defaultModelsDir() : fs::path(c->models);
    const auto models = sagrid::ModelSet::load(modelsDir);
    sagrid::EvaluationOptions options;
    static_cast<sagrid::PassOptions&>(options) = c->passes;
    options.keepCandidates = true;
    options.dataDir = c->data.front();
    options.moreData.assign(c->data.begin() + 1, c->data.end());
    options.features = models.featureOptions();
    options.features.cacheDir = c->cache;
    std::unique_ptr<sagrid::app::ProgressBar> bar;
    options.onProgress = [&](std::size_t done, std::size_t total, const std::string& id) {
      if (!bar) bar = std::make_unique<sagrid::app::ProgressBar>("candidates", total);
      bar->update(done, id);
      if (done == total) bar.reset();
    };
    const auto report = sagrid::evaluateModels(models, options);
    sagrid::writeCandidateSets(c->out, report.candidateSets);
    std::fprintf(stderr, "candidates: %zu model sets of %zu objects -> %s\n",
                 report.candidateSets.size(), report.objects, c->out.c_str());
  });

  struct LearnOptions {
    std::vector<std::string> candidates, guard;
    std::string models, out;
    sagrid::ScorerTrainingOptions training;
    sagrid::ScorerCurveOptions curve;
    std::string compareConfidence;
    std::vector<std::string> withoutFeatures;
    unsigned repeats = 0;
    double leaveOutGenerated = 0.2;
  };
  auto l = std::make_shared<LearnOptions>();
  auto* cv = cmd->add_subcommand(
      "cv", "Leave one source out over the curated real objects of the candidate files: per "
            "source, the count's points, a decision fitted on generated objects only and one "
            "fitted with the curated objects of the other sources; writes OUT/scorer_cv.md, .json "
            "(with --ks also the learning curve as OUT/scorer_cv.png) and OUT/confidence.json "
            "(the object confidence fitted on the points so decided)");
  cv->add_option("--out", l->out, "Report folder (default scorer-cv)");
  cv->add_option("--ks", l->curve.ks,
                 "Learning curve: fit with k curated objects of the other sources too, e.g. "
                 "--ks 0 5 10 20");
  cv->add_option("--seed", l->curve.seed, "Seed of the learning curve's draws (default 1)");
  cv->add_option("--draws", l->curve.draws,
                 "Learning curve: draws of the k objects per fold, the figures pooled over them "
                 "(default 1)")
      ->check(CLI::Range(1u, 100u));
  cv->add_option("--tuned-on", l->curve.tunedOn,
                 "A source a pass or rule was made on (repeatable): the report also gives the "
                 "figures without these sources");
  cv->add_option("--compare-confidence", l->compareConfidence,
                 "A models folder whose confidence.json is checked beside the one fitted on the "
                 "--tuned-on sources, on the other sources' objects (log loss, Brier)");
  cv->add_option("--without-feature", l->withoutFeatures,
                 "A candidate feature the decision does without (repeatable; set to 0 on every "
                 "candidate; MODEL:FEATURE on that model's only): what it adds, leave one source "
                 "out");
  cv->add_option("--repeats", l->repeats,
                 "Repeat the leave one source out this many times, each with a share of the "
                 "generated objects left out of training (seeds --seed, --seed + 1, ...): the "
                 "report's \"Spread over repeats\" says how far the figures move (default 0)")
      ->check(CLI::Range(0u, 100u));
  cv->add_option("--leave-out-generated", l->leaveOutGenerated,
                 "With --repeats: the share of the generated objects each repeat leaves out "
                 "(default 0.2)")
      ->check(CLI::Range(0.0, 0.95));
  addTrainingOptions(*cv, l->candidates, l->training);
  cv->callback([l] {
    if (!l->compareConfidence.empty()) {
      const auto other = sagrid::readConfidenceCalibration(l->compareConfidence);
      if (!other.fitted)
        throw sagrid::FileError(fs::path(l->compareConfidence) / "confidence.json",
                                "no fitted object confidence to compare");
      l->curve.otherConfidence = other;
      l->curve.otherConfidenceName = (fs::path(l->compareConfidence) / "confidence.json").string() +
                                     " (fitted on " + other.fittedOn + ")";
    }
    auto sets = readAll(l->candidates);
    sagrid::withoutFeatures(sets, l->withoutFeatures);
    const auto result = sagrid::crossValidatePointScorer(sets, l->training, l->curve);
    const fs::path out = l->out.empty() ? fs::path("scorer-cv") : fs::path(l->out);
    fs::create_directories(out);
    std::string md = sagrid::scorerCrossValidationMarkdown(result);
    nlohmann::json json = sagrid::toJson(result);
    if (l->repeats > 0) {
      const auto spread = sagrid::scorerCvSpread(sets, l->training, l->curve, l->repeats,
                                                 l->leaveOutGenerated, l->curve.seed);
      md += "\n" + sagrid::scorerCvSpreadMarkdown(spread, result);
      json["spread"] = sagrid::toJson(spread);
    }
    sagrid::writeFileAtomic(out / "scorer_cv.md", md);
    sagrid::writeFileAtomic(out / "scorer_cv.json", json.dump(2) + "\n");
    sagrid::writeScorerLearningCurvePng(result, out / "scorer_cv.png");
    // The object confidence fitted on the points decided leave one source out: a models folder
    // takes it by copying OUT/confidence.json.
    if (result.confidence) sagrid::writeConfidenceCalibration(out, *result.confidence);
    std::cout << md;
  });

  auto* train = cmd->add_subcommand(
      "train", "Fit the decision on every object of the candidate files and write a models "
               "folder: --models' files plus point_scorer.json (annotate, eval and the GUI then "
               "use it)");
  train->add_option("--models", l->models, "Model folder to copy (default resources/models)");
  train->add_option("--out", l->out, "Models folder to write")->required();
  train->add_option("--guard", l->guard,
                    "Candidate files of held-out curated objects (other sources than the "
                    "training's; repeatable): per category, every mix of --models' decisions "
                    "(without one: the points the held-out candidates were made with) and the new "
                    "ones is judged on the category's held-out objects as a whole (its counts read "
                    "each other) and the mix with the fewest edits adopted where it saves more "
                    "than the standard error of the per-object differences, else the current "
                    "decisions stay; refused anywhere, the new scorer also goes to OUT/refused/; "
                    "figures per model and category in OUT/scorer_guard.json");
  train->add_option("--without-feature", l->withoutFeatures,
                    "A candidate feature the decision is fitted without (repeatable; "
                    "MODEL:FEATURE for that model's decision only): it never reads it");
  addTrainingOptions(*train, l->candidates, l->training);
  train->callback([l] {
    auto sets = readAll(l->candidates);
    sagrid::withoutFeatures(sets, l->withoutFeatures);
    std::vector<const sagrid::CandidateSet*> all;
    for (const auto& s : sets) all.push_back(&s);
    const fs::path from = l->models.empty() ? sagrid::defaultModelsDir() : fs::path(l->models);
    const auto guardSets = readAll(l->guard);
    refuseOtherWeights(sets, from);
    refuseOtherWeights(guardSets, from);
    // Unguarded, the current decision is not read: a file of an older build is replaced.
    const auto current = guardSets.empty() ? std::nullopt : sagrid::readPointScorer(from);
    writeModelsWithScorer(from, l->out,
                          sagrid::judgeScorerUpdate(sagrid::trainPointScorer(all, l->training),
                                                    current, guardSets, all));
  });

  struct CompareOptions {
    std::string these, those, out;
  };
  auto pair = std::make_shared<CompareOptions>();
  auto* compare = cmd->add_subcommand(
      "compare", "Two runs of `scorer cv --repeats` on the same curated objects, repeat by "
                 "repeat: per repeat both figures and their difference, the mean and sd of the "
                 "differences, how many repeats need fewer edits and the sign test (markdown on "
                 "stdout)");
  compare->add_option("THIS", pair->these,
                      "A run's scorer_cv.json or its folder; several, comma-separated, are one "
                      "design's runs with other seeds, their repeats pooled")
      ->required();
  compare->add_option("OTHER", pair->those, "The run(s) it is compared with, the same way")
      ->required();
  compare->add_option("--out", pair->out, "Also write the report to this file");
  compare->callback([pair] {
    const auto pooled = [](const std::string& paths) {
      std::vector<sagrid::RecordedScorerCv> runs;
      std::stringstream list(paths);
      for (std::string p; std::getline(list, p, ',');)
        runs.push_back(sagrid::readScorerCv(fs::is_directory(p) ? fs::path(p) / "scorer_cv.json"
                                                                : fs::path(p)));
      return sagrid::pooledScorerCvs(runs);
    };
    const std::string md = sagrid::pairedScorerCvMarkdown(
        sagrid::pairScorerCvs(pooled(pair->these), pooled(pair->those)));
    if (!pair->out.empty()) sagrid::writeFileAtomic(pair->out, md);
    std::cout << md;
  });

  struct UpdateOptions {
    std::string data, generated, heldOut, models, out;
  };
  auto u = std::make_shared<UpdateOptions>();
  auto* upd = cmd->add_subcommand(
      "update", "Retrain the models folder's decision from curated objects in one step, as the "
                "GUI's Train panel does: candidates of --data, of generated objects and of "
                "--held-out made by --models; each model's new decision goes to OUT where it "
                "needs fewer edits on that model's held-out objects (without --held-out: each "
                "category's where it needs fewer edits on --data's objects, each source left out "
                "of the fitting in turn), the others keep theirs, and the new scorer goes to "
                "OUT/refused/ where any model refused it (figures in OUT/scorer_guard.json)");
  upd->add_option("--data", u->data, "Curated training objects (a dataset)")->required();
  upd->add_option("--generated", u->generated,
                  "Generated objects the networks were not trained on (default: the bench's val "
                  "and decision splits, as the shipped decision learned)");
  upd->add_option("--held-out", u->heldOut,
                  "Curated objects of other sources: the guard's (without: --data's objects "
                  "judge, each source left out in turn; unguarded when they are of one source)");
  upd->add_option("--models", u->models, "Models folder (default resources/models)");
  upd->add_option("--out", u->out, "Models folder to write")->required();
  upd->callback([u] {
    sagrid::ScorerUpdateRequest request;
    request.models = u->models.empty() ? sagrid::defaultModelsDir() : fs::path(u->models);
    request.curated = u->data;
    request.generated = u->generated;
    request.heldOut = u->heldOut;
    std::unique_ptr<sagrid::app::ProgressBar> bar;
    std::string current;
    request.onProgress = [&](const std::string& phase, std::size_t done, std::size_t total,
                             const std::string& id) {
      if (phase != current) bar.reset(), current = phase;
      if (!bar) bar = std::make_unique<sagrid::app::ProgressBar>("candidates, " + phase, total);
      bar->update(done, id);
    };
    const sagrid::ScorerUpdate update = sagrid::updatePointScorer(request);
    bar.reset();
    std::fprintf(stderr, "scorer update: %zu curated, %zu generated, %zu held-out model sets\n",
                 update.curatedSets, update.generatedSets, update.heldOutSets);
    writeModelsWithScorer(request.models, u->out, update);
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("scorer", setupScorer);
