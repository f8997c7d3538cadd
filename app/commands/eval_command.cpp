// `sagrid eval --data DIR`: accuracy of the models (and the Embedding Search baselines) on a
// labelled dataset, in the paper's Table II form; `--sweep "arch1;arch2"` trains and compares
// architectures (Table I form). Parsing and progress display only.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/command_registry.h"
#include "app/commands/learning_curve_options.h"
#include "app/commands/pass_options_flags.h"
#include "app/progress_bar.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/resource_paths.h"
#include "core/eval/architecture_sweep.h"
#include "core/eval/count_fitting.h"
#include "core/eval/evaluation.h"
#include "core/common/atomic_file.h"
#include "core/curation/curation_report.h"
#include "core/eval/evaluation_comparison.h"
#include "core/eval/part_agreement.h"
#include "core/eval/part_truth.h"
#include "core/eval/unit_guess_score.h"
#include "core/labels/labels.h"

namespace {
namespace fs = std::filesystem;

void setupEval(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "eval",
      "Evaluate models on a labelled dataset (its val/ split when present): mean error to the "
      "nearest "
      "ground truth (paper), Hungarian-matched error, precision/recall within 5 cm, right counts; "
      "SAGrid and "
      "Embedding Search baselines. Writes OUT/eval.md, eval.json, eval.png. With --sweep, trains "
      "each "
      "architecture on DATA/train and compares them on DATA/val (Table I form).");
  struct Options {
    std::vector<std::string> data;
    std::string models, out = "eval", cache, sweep, mode = "sparse", fitConfidence, fitCounts,
                        countObjective = "count";
    std::vector<std::string> only, compare;
    std::string curation, units, truth, savePartTruth;
    std::vector<std::string> partTruth;
    bool parts = false;
    double minutes = 2;
    int epochs = 0;
    sagrid::PassOptions passes;
    double nearWeight = sagrid::SweepOptions{}.nearWeight;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--data", o->data,
                  "Labelled dataset (manifest.jsonl or object folders; its val/ split when it has "
                  "one); repeat it to evaluate several together (one report over their union, "
                  "e.g. --fit-confidence on generated and real objects)");
  cmd->add_option("--units", o->units,
                  "Instead of models: score the units guesses an `annotate --out` folder recorded "
                  "against the curated units of --truth (<folder of the mesh>/labels.json); writes "
                  "OUT/units.md");
  cmd->add_option("--truth", o->truth, "With --units: the curated labels folder");
  cmd->add_option("--curation", o->curation,
                  "Instead of models: report curator throughput from a GUI curation log "
                  "(actions and edits per object, the one-key share, the slowest objects, time as "
                  "logged and by a keystroke-level model); writes OUT/curation.md and .json");
  cmd->add_flag("--parts", o->parts,
               "Instead of models: the control parts annotate finds at the curated toggle points "
               "against the controls the curator confirmed in the GUI (kept, reshaped with the "
               "brush, Grow or Shrink, or given an axis, motion, pivot or burner) in --data's "
               "labels: triangle IoU by area and axis angle per part, and for a knob the angle "
               "between the mark and the knob's own axis of rotational symmetry; writes "
               "OUT/parts.md and .json");
  cmd->add_option("--part-truth", o->partTruth,
                  "With --parts: measure against the curator's parts kept in this file (per object "
                  "folder and point, with the mesh's sha256; resources/datasets/*/part_truth.json) "
                  "instead of the controls confirmed in --data's labels; repeat for several");
  cmd->add_option("--save-part-truth", o->savePartTruth,
                  "With --parts: also keep the controls confirmed in --data's labels in this file, "
                  "as --part-truth reads it");
  cmd->add_option("--models", o->models, "Model folder (default resources/models)");
  cmd->add_option("--out", o->out, "Report folder (default eval)");
  cmd->add_option("--compare", o->compare,
                  "Other model folders to evaluate on the same objects (repeatable); writes "
                  "OUT/compare.md + compare.json with every set side by side and each set's own "
                  "report in OUT/compare-<n>/");
  cmd->add_option("--cache", o->cache, "Feature cache (default DATA/.sagrid-cache)");
  cmd->add_option("--fit-confidence", o->fitConfidence,
                  "Fit the object confidence (P(right with one key)) on this data and write "
                  "DIR/confidence.json (put it beside the models to use it)");
  sagrid::app::addPassOptions(*cmd, o->passes);
  cmd->add_option("--fit-counts", o->fitCounts,
                  "Refit each model's automatic instance count on the fields of this data and "
                  "write a models folder DIR with the refitted cards (eval it with --models DIR)");
  cmd->add_option("--count-objective", o->countObjective,
                  "With --fit-counts: what the refit optimises, the share of right counts "
                  "(count, the default) or the curator's point edits (edits)")
      ->check(CLI::IsMember({"count", "edits"}));
  cmd->add_option("--sweep", o->sweep, "Architectures to compare, ';'-separated Table I strings");
  cmd->add_option("--sweep-models", o->only,
                  "With --sweep: the models to train (default all four)");
  cmd->add_option("--minutes", o->minutes, "With --sweep: training budget per model (default 2)");
  cmd->add_option("--epochs", o->epochs, "With --sweep: epochs per model instead of --minutes");
  cmd->add_option("--near-weight", o->nearWeight,
                  "With --sweep: near-instance loss weight (default 30, as the shipped models)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--mode", o->mode, "With --sweep: sparse or dense")
      ->check(CLI::IsMember({"sparse", "dense"}));
  const auto learningCurve = sagrid::app::addLearningCurveOptions(*cmd);
  cmd->callback([o, learningCurve, cmd] {
    if ((!o->partTruth.empty() || !o->savePartTruth.empty()) && !o->parts)
      throw sagrid::InvalidArgument("eval: --part-truth and --save-part-truth go with --parts");
    if (!o->curation.empty()) {
      const sagrid::CurationReport report = sagrid::curationReport(sagrid::readCurationLog(o->curation));
      fs::create_directories(o->out);
      sagrid::writeFileAtomic(fs::path(o->out) / "curation.md", sagrid::curationMarkdown(report));
      sagrid::writeFileAtomic(fs::path(o->out) / "curation.json", sagrid::toJson(report).dump(2) + "\n");
      std::cout << sagrid::curationMarkdown(report);
      return;
    }
    if (!o->units.empty()) {
      if (o->truth.empty()) throw sagrid::InvalidArgument("eval --units needs --truth DIR");
      std::vector<std::pair<sagrid::ObjectLabels, sagrid::ObjectLabels>> pairs;
      for (const auto& entry : fs::directory_iterator(o->units)) {
        const fs::path file = entry.path() / "labels.json";
        if (!fs::is_regular_file(file)) continue;
        sagrid::ObjectLabels predicted = sagrid::readLabels(file);
        const fs::path truth = fs::path(o->truth) / fs::path(predicted.object.mesh).parent_path().filename() / "labels.json";
        if (fs::is_regular_file(truth)) pairs.emplace_back(std::move(predicted), sagrid::readLabels(truth));
      }
      const std::string md = sagrid::unitGuessMarkdown(sagrid::scoreUnitGuesses(pairs));
      fs::create_directories(o->out);
      sagrid::writeFileAtomic(fs::path(o->out) / "units.md", md);
      std::cout << md;
      return;
    }
    if (o->data.empty()) throw sagrid::InvalidArgument("eval: --data is required (or --curation LOG)");
    if (o->parts) {
      std::vector<sagrid::DatasetEntry> entries;
      for (const auto& dir : o->data) {
        auto some = sagrid::readDataset(dir);
        entries.insert(entries.end(), some.begin(), some.end());
      }
      if (!o->savePartTruth.empty())
        sagrid::writeFileAtomic(o->savePartTruth, sagrid::partTruthText(sagrid::partTruthOf(entries)));
      std::optional<sagrid::PartTruth> truth;
      if (!o->partTruth.empty())
        truth = sagrid::readPartTruths({o->partTruth.begin(), o->partTruth.end()});
      const sagrid::PartAgreementReport report =
          sagrid::measurePartAgreement(entries, truth ? &*truth : nullptr);
      fs::create_directories(o->out);
      sagrid::writeFileAtomic(fs::path(o->out) / "parts.md", sagrid::partAgreementMarkdown(report));
      sagrid::writeFileAtomic(fs::path(o->out) / "parts.json", sagrid::toJson(report).dump(2) + "\n");
      std::cout << sagrid::partAgreementMarkdown(report);
      return;
    }
    auto oneDataset = [&](const char* what) {
      if (o->data.size() != 1)
        throw sagrid::InvalidArgument(std::string(what) + " takes one --data, got " +
                                      std::to_string(o->data.size()));
      return o->data.front();
    };
    if (learningCurve->enabled) oneDataset("--learning-curve");
    if (sagrid::app::runLearningCurveIfAsked(*learningCurve, *cmd, o->data.front(), o->out,
                                             o->cache, o->minutes, o->epochs))
      return;
    std::unique_ptr<sagrid::app::ProgressBar> bar;
    auto progress = [&](std::size_t done, std::size_t total, const std::string& id) {
      if (!bar) bar = std::make_unique<sagrid::app::ProgressBar>("eval", total);
      bar->update(done, id);
      if (done == total) bar.reset();
    };
    if (!o->sweep.empty()) {
      sagrid::SweepOptions s;
      s.dataDir = oneDataset("--sweep");
      s.outDir = o->out;
      s.architectures = sagrid::splitArchitectures(o->sweep);
      if (!o->only.empty()) s.modelNames = o->only;
      s.minutes = o->minutes;
      s.epochs = o->epochs;
      s.mode = o->mode;
      s.nearWeight = static_cast<float>(o->nearWeight);
      if (!o->cache.empty()) s.cacheDir = o->cache;
      s.onProgress = progress;
      const auto result = sagrid::runArchitectureSweep(s);
      std::cout << sagrid::sweepMarkdown(result);
      std::fprintf(stderr, "sweep report: %s\n", (fs::path(o->out) / "sweep.md").string().c_str());
      return;
    }
    const fs::path modelsDir = !o->models.empty() ? fs::path(o->models) : sagrid::defaultModelsDir();
    const auto models = sagrid::ModelSet::load(modelsDir);
    sagrid::EvaluationOptions options;
    options.dataDir = o->data.front();
    options.moreData.assign(o->data.begin() + 1, o->data.end());
    options.features = models.featureOptions();
    options.features.cacheDir = o->cache;
    options.onProgress = progress;
    options.confidence = sagrid::readConfidenceCalibration(modelsDir);
    options.keepFields = !o->fitCounts.empty();
    static_cast<sagrid::PassOptions&>(options) = o->passes;
    const auto report = sagrid::evaluateModels(models, options);
    const std::string dataText = sagrid::evaluatedData(report);
    if (!o->fitCounts.empty()) {
      const auto fits =
          sagrid::fitCounts(models, report,
                            o->countObjective == "edits" ? sagrid::CountObjective::CuratorEdits
                                                         : sagrid::CountObjective::RightCount);
      sagrid::writeModelsWithFittedCounts(modelsDir, fits, o->fitCounts);
      std::fprintf(stderr, "counts: refitted on %s -> %s\n%s", dataText.c_str(),
                   o->fitCounts.c_str(), sagrid::countFitMarkdown(fits).c_str());
    }
    if (!o->fitConfidence.empty()) {
      auto fit = sagrid::fitConfidence(report.confidenceSignal, report.oneKey);
      fit.fittedOn = dataText;
      fit.networkWeights = models.weightsByModel();
      fs::create_directories(o->fitConfidence);
      sagrid::writeConfidenceCalibration(o->fitConfidence, fit);
      std::fprintf(stderr, "confidence: fitted on %zu objects (%.0f %% right with one key) -> %s\n",
                   fit.objects, 100 * fit.oneKeyShare,
                   (fs::path(o->fitConfidence) / sagrid::kConfidenceFile).string().c_str());
    }
    sagrid::writeEvaluationReport(report, o->out);
    std::cout << sagrid::evaluationMarkdown(report);
    std::fprintf(stderr, "report: %s/eval.md, eval.json, eval.png\n", o->out.c_str());
    if (o->compare.empty()) return;
    std::vector<sagrid::EvaluationReport> others;
    others.reserve(o->compare.size());
    for (std::size_t i = 0; i < o->compare.size(); ++i) {
      const auto otherModels = sagrid::ModelSet::load(o->compare[i]);
      sagrid::EvaluationOptions other = options;
      other.features = otherModels.featureOptions();
      other.features.cacheDir = o->cache;
      other.confidence = sagrid::readConfidenceCalibration(o->compare[i]);
      others.push_back(sagrid::evaluateModels(otherModels, other));
      sagrid::writeEvaluationReport(others.back(),
                                    fs::path(o->out) / ("compare-" + std::to_string(i + 1)));
    }
    std::vector<sagrid::LabelledReport> table{{modelsDir.string(), &report}};
    for (std::size_t i = 0; i < others.size(); ++i) table.push_back({o->compare[i], &others[i]});
    const std::string md = sagrid::comparisonMarkdown(table);
    sagrid::writeFileAtomic(fs::path(o->out) / "compare.md", md);
    sagrid::writeFileAtomic(fs::path(o->out) / "compare.json",
                            sagrid::comparisonJson(table).dump(2) + "\n");
    std::cout << '\n' << md;
    std::fprintf(stderr, "comparison: %s/compare.md, compare.json\n", o->out.c_str());
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("eval", setupEval);
