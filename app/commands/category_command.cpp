// `sagrid category train|eval|cv|split`: the category classifier with rejection (stove | sink |
// none) that `annotate`, `filter --like` and the GUI use when the models folder has category.json.
// Parsing, progress and printing only; the work is in core/annotate/category_*.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "app/command_registry.h"
#include "app/progress_bar.h"
#include "core/annotate/category_cross_validation.h"
#include "core/annotate/category_evidence.h"
#include "core/annotate/category_training.h"
#include "core/annotate/category_update.h"
#include "core/annotate/model_set.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/resource_paths.h"
#include "core/dataset/dataset.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "core/model/model_card.h"

namespace {
namespace fs = std::filesystem;

using sagrid::defaultModelsDir;  // ./resources, <bin>/../share/sagrid or the source tree


// Descriptors of every --data folder (DIR@W weighs its objects W times), minus the excluded ids,
// with a progress bar per folder.
std::vector<sagrid::CategorySample> collect(const std::vector<std::string>& dirs,
                                            const sagrid::FeatureOptions& features,
                                            const std::set<std::string>& exclude,
                                            const sagrid::CategoryInputSet& inputs) {
  std::vector<sagrid::WeightedFolder> folders;
  for (const auto& arg : dirs) folders.push_back(sagrid::parseWeightedFolder(arg));
  std::unique_ptr<sagrid::app::ProgressBar> bar;
  fs::path barDir;
  std::vector<std::size_t> skipped;
  auto samples = sagrid::collectWeightedSamples(
      folders, features, exclude, inputs,
      [&](const fs::path& dir, std::size_t done, std::size_t total) {
        if (!bar || barDir != dir) {
          if (bar) bar->finish();
          bar = std::make_unique<sagrid::app::ProgressBar>("features " + dir.string(), total);
          barDir = dir;
        }
        bar->update(done);
      },
      &skipped);
  if (bar) bar->finish();
  for (std::size_t f = 0; f < folders.size(); ++f)
    if (skipped[f])
      std::fprintf(stderr, "%s: %zu objects skipped (features failed)\n",
                   folders[f].dir.string().c_str(), skipped[f]);
  return samples;
}

// Feature options of the cards in `modelsDir` (the classifier must see what they saw); the
// defaults when the folder has no cards.
sagrid::FeatureOptions featuresFor(const fs::path& modelsDir) {
  if (fs::is_directory(modelsDir) && !sagrid::model::listModelCards(modelsDir).empty())
    return sagrid::ModelSet::load(modelsDir).featureOptions();
  return {};
}

struct Options {
  std::vector<std::string> data, validate, gated, guard, guardBySource;
  int folds = 5;
  bool bySource = false;  // category cv: leave one source out
  std::string out, models, exclude, split, splitOut, up, cache, decisions;
  double threshold = -1, l2 = 1e-2, keep = 0.98, sureAbove = 0;
  int iterations = 20000, treeRounds = 100, treeDepth = 3;
  float treeRowShare = 1.0f, treeFeatureShare = 1.0f;
  std::optional<double> nameWeight;  // --name-weight: fixed instead of fitted
  bool trees = false;
  bool retrieval = false, linear = false, evidence = false;
  sagrid::CategoryInputSet inputs;
};

// The evidence of a category on a sample: its models run on the sample's mesh (in its labelled
// up axis, else --up) as `annotate --category` would, features from --cache when given, else from
// the cache its descriptor came from (no second feature extraction).
class SampleEvidence {
 public:
  SampleEvidence(const sagrid::ModelSet& models, const Options& o) : m_models(models) {
    m_options.features = models.featureOptions();
    m_options.features.cacheDir = o.cache;
    if (!o.up.empty()) m_options.features.up = sagrid::parseUpAxis(o.up);
  }
  double operator()(const sagrid::CategorySample& s, const std::string& category) const {
    auto options = m_options;
    if (!s.up.empty()) options.features.up = sagrid::parseUpAxis(s.up);
    if (options.features.cacheDir.empty()) options.features.cacheDir = s.featureCache;
    return sagrid::affordanceEvidence(s.mesh, category, m_models, options);
  }
  // The classifier's decision on `s` after the models folder's evidence gate, as annotate decides.
  sagrid::CategoryDecision gate(const sagrid::CategorySample& s,
                                const sagrid::CategoryDecision& d) const {
    const auto* classifier = m_models.categoryClassifier();
    if (!classifier) return d;
    return sagrid::applyEvidenceGate(
        d, classifier->evidence,
        [&](const std::string& category) { return (*this)(s, category); });
  }

 private:
  const sagrid::ModelSet& m_models;
  sagrid::AnnotateOptions m_options;
};

// --evidence needs the folder's classifier to carry a gate.
void requireEvidenceGate(const sagrid::CategoryClassifier* classifier, const fs::path& dir) {
  if (!classifier || classifier->evidence.empty())
    throw sagrid::InvalidArgument(dir.string() +
                                  ": --evidence needs a category classifier with an evidence gate "
                                  "(`sagrid category evidence`)");
}

void addEvidenceFlags(CLI::App* cmd, Options& o) {
  cmd->add_flag("--evidence", o.evidence,
                "Follow the classifier with the models folder's evidence gate: an object filed "
                "under a category whose models find no point of it (below the gate's threshold) is "
                "rejected, as `annotate` does (runs the models on every accepted object)");
  cmd->add_option("--cache", o.cache,
                  "Feature cache folder for the models' runs (default: each dataset's "
                  ".sagrid-cache, where the descriptors are cached)");
}

// The options that shape a trained classifier (train and cv).
void addTrainingFlags(CLI::App* cmd, Options& o) {
  cmd->add_option("--threshold", o.threshold,
                  "Rejection threshold on the best category's probability (default 0.5)");
  cmd->add_option("--l2", o.l2, "L2 penalty on the weights");
  cmd->add_option("--up", o.up, "Up axis (y or z) of objects whose labels do not say")
      ->check(CLI::IsMember({"y", "z"}));
  cmd->add_option("--iterations", o.iterations, "Gradient steps")->check(CLI::PositiveNumber);
  cmd->add_flag("--linear", o.linear, "Inputs only, without their squares");
  cmd->add_flag("--trees", o.trees,
                "Boosted trees per class (one against the rest) instead of the softmax");
  cmd->add_option("--tree-rounds", o.treeRounds, "With --trees: boosting rounds per class")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--tree-depth", o.treeDepth, "With --trees: depth of each tree")
      ->check(CLI::Range(1, 8));
  cmd->add_option("--tree-row-share", o.treeRowShare,
                  "With --trees: share of the objects each tree is grown on, drawn per tree "
                  "(stochastic boosting; default 1, all)")
      ->check(CLI::Range(0.01, 1.0));
  cmd->add_option("--tree-feature-share", o.treeFeatureShare,
                  "With --trees: share of the inputs each tree may split on, drawn per tree "
                  "(default 1, all)")
      ->check(CLI::Range(0.01, 1.0));
  cmd->add_flag("--top-relief", o.inputs.topRelief,
                "Also read the relief of the object's top from its voxels (basins, burner spots, "
                "flat lids), beside the descriptor");
  cmd->add_flag("--part-statistics", o.inputs.partStatistics,
                "Also read the statistics of the mesh's parts (its families of copies: burner "
                "caps, rows of knobs, a tap's handles; their size and height), beside the "
                "descriptor");
  cmd->add_flag("--file-name", o.inputs.fileName,
                "Also read the words of the mesh file's name (\"kitchenStove.glb\": kitchen, "
                "stove), learned from the curated objects' published names (labels holding the "
                "file's sha256; generated objects do not teach): naive Bayes over the words, "
                "multiplied into the shape's probabilities, their likelihoods weighed as the "
                "curated objects of each source, decided without it, were likeliest");
  cmd->add_option("--name-weight", o.nameWeight,
                  "With --file-name: weigh the words' likelihoods by this power instead of "
                  "fitting it (1: the Bayes rule, as before session 66)")
      ->check(CLI::Range(0.0, sagrid::kMaxNameWeight));
}

sagrid::CategoryTrainingOptions trainingOptions(const Options& o) {
  sagrid::CategoryTrainingOptions options;
  options.inputs = o.inputs;
  options.l2 = o.l2;
  options.iterations = o.iterations;
  options.quadratic = !o.linear;
  options.trees = o.trees;
  options.boosting.rounds = o.treeRounds;
  options.boosting.depth = o.treeDepth;
  options.boosting.rowShare = o.treeRowShare;
  options.boosting.featureShare = o.treeFeatureShare;
  options.nameWeight = o.nameWeight;
  if (o.threshold >= 0) options.threshold = o.threshold;
  return options;
}

// How a classifier that reads file names weighs them (CategoryClassifier::training's record).
void printNameWeight(const nlohmann::json& training) {
  if (!training.contains("file_name_weight")) return;
  const nlohmann::json& w = training.at("file_name_weight");
  const double weight = w.value("weight", 1.0);
  const nlohmann::json likelihood = w.value("log_likelihood", nlohmann::json::object());
  if (w.value("fixed", false))
    std::fprintf(stderr, "file names weighed %.3g (--name-weight)\n", weight);
  else if (w.value("held_out_objects", 0) == 0)
    std::fprintf(stderr,
                 "file names weighed 1 (the Bayes rule): no curated names of two sources "
                 "to learn a weight from\n");
  else
    std::fprintf(stderr,
                 "file names weighed %.3g: the likeliest weight for %d curated objects of %d "
                 "sources, each decided without its source (log-likelihood %.1f by the Bayes "
                 "rule, %.1f weighed)\n",
                 weight, w.value("held_out_objects", 0), w.value("sources", 0),
                 likelihood.value("bayes_rule", 0.0), likelihood.value("fitted", 0.0));
}

// The guard on a classifier update (core/annotate/category_update.h): the verdict goes to stdout
// and OUT/guard.jsonl.
bool guardAdopts(const sagrid::CategoryClassifier& candidate, const fs::path& current,
                 const std::vector<std::string>& heldOut, const sagrid::FeatureOptions& features) {
  std::vector<sagrid::WeightedFolder> folders;
  for (const auto& dir : heldOut) folders.push_back(sagrid::parseWeightedFolder(dir));
  const sagrid::CategoryVerdict verdict =
      sagrid::judgeCategoryUpdate(candidate, current, folders, features);
  std::printf("%s\n", verdict.reason.c_str());
  sagrid::recordCategoryVerdict(verdict, current.parent_path(), heldOut);
  return verdict.adopted;
}

// The guard judged by source (judgeCategoryUpdateBySource): the recipe of --data and `options`
// against the current file; the verdict goes to stdout and OUT/guard.jsonl. Adopted without a
// current file.
bool guardBySourceAdopts(const Options& o, const sagrid::CategoryTrainingOptions& options,
                         const fs::path& current, const sagrid::FeatureOptions& features) {
  std::error_code ec;
  if (!fs::exists(current, ec)) {
    std::printf("category classifier: no current one in %s to judge against: adopted\n",
                current.parent_path().string().c_str());
    return true;
  }
  sagrid::CategoryRecipe candidate{{}, options};
  for (const auto& arg : o.data) candidate.folders.push_back(sagrid::parseWeightedFolder(arg));
  std::vector<fs::path> curated(o.guardBySource.begin(), o.guardBySource.end());
  const sagrid::CategoryVerdict verdict = sagrid::judgeCategoryUpdateBySource(
      candidate, sagrid::CategoryClassifier::load(current), curated, features, {},
      [](const std::string& recipe, int k, int folds) {
        std::fprintf(stderr, "guard: %s recipe, source %d/%d\n", recipe.c_str(), k + 1, folds);
      });
  std::printf("%s\n", verdict.reason.c_str());
  sagrid::recordCategoryVerdict(verdict, current.parent_path(), o.guardBySource);
  return verdict.adopted;
}

void setupCategory(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "category",
      "The category classifier with rejection (stove | sink | none): train it into the models "
      "folder (category.json), evaluate it, or split a folder's ids for training and validation.");
  cmd->require_subcommand(1);

  auto o = std::make_shared<Options>();

  auto* train = cmd->add_subcommand(
      "train",
      "Train the classifier on labelled dataset folders (stove and sink objects; every other "
      "category, e.g. \"none\" from `generate --preset distractors`, is a distractor) and write "
      "OUT/category.json.");
  train->add_option("--data", o->data,
                    "Dataset folder (repeat for several); DIR@W weighs its objects W times")
      ->required();
  train->add_option("--out", o->out, "Models folder to write category.json into (default resources/models)");
  train->add_option("--exclude-split", o->exclude,
                    "Id split file (category split): its val ids are held out of training");
  train->add_option("--guard", o->guard,
                    "Held-out dataset folders (curated objects of other sources than --data; "
                    "repeat): the new classifier replaces OUT's only if its share right there, "
                    "averaged over stoves, sinks and look-alikes, is higher by more than the "
                    "standard error of the per-object differences; else it goes to "
                    "OUT/refused/ (OUT/guard.jsonl: the figures)");
  train
      ->add_option("--guard-by-source", o->guardBySource,
                   "Curated dataset folders (repeat; usually also among --data): the new "
                   "classifier's recipe and the current one's (OUT's training record; where a "
                   "folder of that is not here, the current classifier as it is) are each "
                   "cross-validated leaving one source of these objects out at a time; the new "
                   "one replaces OUT's only if its share right, averaged over stoves, sinks and "
                   "look-alikes, is higher by more than the standard error of the per-object "
                   "differences; else it goes to OUT/refused/ (OUT/guard.jsonl: the "
                   "figures)")
      ->excludes(train->get_option("--guard"))
      ->excludes(train->get_option("--exclude-split"));
  addTrainingFlags(train, *o);
  train->callback([o] {
    const fs::path out = o->out.empty() ? defaultModelsDir() : fs::path(o->out);
    auto features = featuresFor(out);
    if (!o->up.empty()) features.up = sagrid::parseUpAxis(o->up);
    std::set<std::string> exclude;
    if (!o->exclude.empty()) exclude = sagrid::readIdSplit(o->exclude).val;
    const auto samples = collect(o->data, features, exclude, o->inputs);
    const auto options = trainingOptions(*o);
    auto classifier = sagrid::CategoryClassifier::train(samples, options);
    classifier.featureBackend = features.backend;
    classifier.featureConfigHash = sagrid::featureConfigHash(features);
    classifier.gridResolution = features.resolution;
    classifier.training["data"] = o->data;
    if (!o->exclude.empty()) classifier.training["held_out_split"] = o->exclude;
    std::string command = "sagrid category train";
    for (const auto& d : o->data) command += " --data " + d;
    if (!o->exclude.empty()) command += " --exclude-split " + o->exclude;
    if (!o->up.empty()) command += " --up " + o->up;
    command += " --out " + out.string() + " --threshold " + std::to_string(options.threshold) +
               " --l2 " + std::to_string(o->l2) + " --iterations " + std::to_string(o->iterations) +
               (o->linear ? " --linear" : "") + (o->inputs.topRelief ? " --top-relief" : "") +
               (o->inputs.partStatistics ? " --part-statistics" : "") +
               (o->inputs.fileName ? " --file-name" : "") +
               (o->nameWeight ? " --name-weight " + std::to_string(*o->nameWeight) : "") +
               (o->trees ? " --trees --tree-rounds " + std::to_string(o->treeRounds) +
                               " --tree-depth " + std::to_string(o->treeDepth) +
                               (o->treeRowShare < 1
                                    ? " --tree-row-share " + std::to_string(o->treeRowShare)
                                    : "") +
                               (o->treeFeatureShare < 1
                                    ? " --tree-feature-share " + std::to_string(o->treeFeatureShare)
                                    : "")
                         : "");
    classifier.training["command"] = command;
    const auto ev = sagrid::evaluateCategories(
        [&](const sagrid::CategorySample& s) { return classifier.classify(s); }, samples);
    for (const auto& [cls, c] : ev.byClass)
      classifier.training["train_share_right"][cls] = c.total ? double(c.right) / c.total : 0.0;
    fs::path file = out / sagrid::kCategoryClassifierFile;
    // The folder's evidence gate belongs to its point models, not to the classifier: a retrained
    // classifier keeps it (as the GUI's retraining does); `category evidence` refits it.
    if (fs::exists(file)) classifier.evidence = sagrid::CategoryClassifier::load(file).evidence;
    if (!o->guard.empty() && !guardAdopts(classifier, file, o->guard, features))
      file = out / "refused" / sagrid::kCategoryClassifierFile;
    if (!o->guardBySource.empty() && !guardBySourceAdopts(*o, options, file, features))
      file = out / "refused" / sagrid::kCategoryClassifierFile;
    fs::create_directories(file.parent_path());
    classifier.save(file);
    std::cout << "# training objects\n\n" << sagrid::categoryEvaluationTable(ev) << "\n";
    std::fprintf(stderr, "wrote %s (%zu objects)\n", file.string().c_str(), samples.size());
    printNameWeight(classifier.training);
  });

  auto* eval = cmd->add_subcommand(
      "eval",
      "Category table on labelled dataset folders: share right on stoves, on sinks, and share of "
      "distractors rejected (with the models folder's classifier, or retrieval without one).");
  eval->add_option("--data", o->data, "Dataset folder (repeat for several)")->required();
  eval->add_option("--models", o->models, "Models folder (default resources/models)");
  eval->add_option("--split", o->split, "Id split file: its train ids are left out (evaluate on val)");
  eval->add_option("--threshold", o->threshold, "Rejection threshold (default: the file's)");
  eval->add_option("--up", o->up, "Up axis (y or z) of objects whose labels do not say")
      ->check(CLI::IsMember({"y", "z"}));
  eval->add_flag("--retrieval", o->retrieval,
                 "Evaluate today's retrieval by similarity (no rejection) instead of the classifier");
  addEvidenceFlags(eval, *o);
  eval->callback([o] {
    const fs::path dir = o->models.empty() ? defaultModelsDir() : fs::path(o->models);
    const auto models = sagrid::ModelSet::load(dir);
    std::set<std::string> exclude;
    if (!o->split.empty()) exclude = sagrid::readIdSplit(o->split).train;
    auto features = models.featureOptions();
    if (!o->up.empty()) features.up = sagrid::parseUpAxis(o->up);
    const auto* classifier = models.categoryClassifier();
    const auto samples =
        collect(o->data, features, exclude,
                classifier && !o->retrieval ? classifier->inputSet() : sagrid::CategoryInputSet{});
    if (!classifier && !o->retrieval)
      std::fprintf(stderr, "%s has no %s: evaluating retrieval\n", dir.string().c_str(),
                   sagrid::kCategoryClassifierFile);
    const double threshold = o->threshold >= 0 ? o->threshold : classifier ? classifier->threshold() : 0.5;
    if (o->evidence) requireEvidenceGate(o->retrieval ? nullptr : classifier, dir);
    const SampleEvidence evidence(models, *o);
    std::unique_ptr<sagrid::app::ProgressBar> bar;
    if (o->evidence) bar = std::make_unique<sagrid::app::ProgressBar>("evidence", samples.size());
    std::size_t done = 0;
    const auto ev = sagrid::evaluateCategories(
        [&](const sagrid::CategorySample& s) {
          if (bar) bar->update(done++);
          if (classifier && !o->retrieval) {
            const auto d = classifier->classify(s.descriptor, s.nameWords, threshold);
            return o->evidence ? evidence.gate(s, d) : d;
          }
          sagrid::CategoryDecision r;
          const auto ranked = models.rankCategories(s.descriptor);
          r.category = r.best = ranked.front().category;
          r.score = ranked.front().similarity;
          return r;
        },
        samples);
    if (bar) bar->finish();
    std::cout << sagrid::categoryEvaluationTable(ev);
  });

  auto* cv = cmd->add_subcommand(
      "cv",
      "Cross-validate the classifier over a few real objects: split the --validate folders' "
      "objects into K folds (by sha256 of the id); each fold is decided by a classifier trained "
      "on the --data folders and the other folds. Prints the category table over every "
      "validated object.");
  cv->add_option("--data", o->data,
                 "Dataset folder always trained on (repeat); DIR@W weighs its objects W times")
      ->required();
  cv->add_option("--validate", o->validate,
                 "Dataset folder whose objects are cross-validated (repeat); DIR@W weighs them W "
                 "times while they train")
      ->required();
  cv->add_option("--folds", o->folds, "Number of folds (default 5)")->check(CLI::Range(2, 1000));
  cv->add_flag("--by-source", o->bySource,
               "Leave one source out instead of --folds: each source of the validated objects "
               "(a wild-pool repository, a Sweet Home 3D library, else the dataset folder) is a "
               "fold, decided by a classifier that saw none of its objects");
  cv->add_option("--models", o->models,
                 "Models folder whose feature settings to use (default resources/models)");
  cv->add_option(
      "--decisions", o->decisions,
      "Also write every validated object's decision to this file, one JSON object a "
      "line: id, group, source, mesh, truth, decided category, each class's probability "
      "as decided and from the shape alone, the words of its file's name that moved it and "
      "their weight");
  addTrainingFlags(cv, *o);
  addEvidenceFlags(cv, *o);
  cv->callback([o] {
    const fs::path dir = o->models.empty() ? defaultModelsDir() : fs::path(o->models);
    auto features = featuresFor(dir);
    if (!o->up.empty()) features.up = sagrid::parseUpAxis(o->up);
    const auto always = collect(o->data, features, {}, o->inputs);
    const auto validated = collect(o->validate, features, {}, o->inputs);
    std::optional<sagrid::ModelSet> models;
    std::optional<SampleEvidence> evidence;
    if (o->evidence) {
      models = sagrid::ModelSet::load(dir);
      requireEvidenceGate(models->categoryClassifier(), dir);
      evidence.emplace(*models, *o);
    }
    // Each fold's classifier, then the shipped evidence gate (fitted on objects of the category
    // only: it never saw a distractor).
    const auto onFold = [](int k, int folds) { std::fprintf(stderr, "fold %d/%d: training\n", k + 1, folds); };
    std::string decisions;  // --decisions: a JSON line per validated object
    sagrid::CategoryCheck check;
    if (evidence || !o->decisions.empty())
      check = [&](const sagrid::CategorySample& s, const sagrid::CategoryDecision& d) {
        const sagrid::CategoryDecision decided = evidence ? evidence->gate(s, d) : d;
        if (!o->decisions.empty())
          decisions += nlohmann::json{{"id", s.id},
                                      {"group", s.group},
                                      {"source", s.source},
                                      {"mesh", s.mesh.string()},
                                      {"truth", sagrid::categoryClass(s.category)},
                                      {"decided", decided.category},
                                      {"probabilities", decided.probabilities},
                                      {"shape_probabilities", decided.shapeProbabilities},
                                      {"name_words", decided.nameWords},
                                      {"name_weight", decided.nameWeight}}
                           .dump() +
                       "\n";
        return decided;
      };
    const auto ev = o->bySource
                        ? sagrid::crossValidateCategoriesBySource(always, validated, trainingOptions(*o), onFold, check)
                        : sagrid::crossValidateCategories(always, validated, o->folds, trainingOptions(*o), onFold, check);
    if (!o->decisions.empty()) sagrid::writeFileAtomic(o->decisions, decisions);
    std::cout << "# " << (o->bySource ? std::string("leave-one-source-out") : std::to_string(o->folds) + "-fold")
              << " cross-validation over " << validated.size() << " objects\n\n"
              << sagrid::categoryEvaluationTable(ev);
  });

  auto* evidenceCmd = cmd->add_subcommand(
      "evidence",
      "Fit the evidence gate of the models folder's classifier: run each category's models on "
      "the stove and sink objects of the --data folders (as `annotate --category`) and set, per "
      "category, the threshold on the best point's confidence that --keep of them reach. "
      "Distractors in the folders are only reported (the share each threshold would reject).");
  evidenceCmd->add_option("--data", o->data, "Dataset folder (repeat for several)")->required();
  evidenceCmd->add_option(
      "--models", o->models,
      "Models folder whose category.json gets the gate (default resources/models)");
  evidenceCmd
      ->add_option("--keep", o->keep,
                   "Share of each category's objects the gate keeps (default 0.98)")
      ->check(CLI::Range(0.01, 1.0));
  evidenceCmd->add_option("--up", o->up, "Up axis (y or z) of objects whose labels do not say")
      ->check(CLI::IsMember({"y", "z"}));
  evidenceCmd->add_option("--cache", o->cache,
                          "Feature cache folder (default: each dataset's .sagrid-cache, where "
                          "the descriptors are cached)");
  evidenceCmd
      ->add_option("--sure-above", o->sureAbove,
                   "Ask the models only where the classifier is unsure: a category decided with at "
                   "least this probability stands whatever its evidence (0, the default: every "
                   "decision is checked)")
      ->check(CLI::Range(0.0, 1.0));
  evidenceCmd->add_option("--category", o->gated,
                          "Category to gate (repeat; default: every category with models); the "
                          "others keep no threshold");
  evidenceCmd->callback([o] {
    const fs::path dir = o->models.empty() ? defaultModelsDir() : fs::path(o->models);
    const fs::path file = dir / sagrid::kCategoryClassifierFile;
    auto classifier = sagrid::CategoryClassifier::load(file);
    const auto models = sagrid::ModelSet::load(dir);
    auto features = models.featureOptions();
    if (!o->up.empty()) features.up = sagrid::parseUpAxis(o->up);
    const auto samples = collect(o->data, features, {}, classifier.inputSet());
    const SampleEvidence evidence(models, *o);
    const std::vector<std::string> gated = o->gated.empty() ? models.categories() : o->gated;
    auto isGated = [&gated](const std::string& c) {
      return std::find(gated.begin(), gated.end(), c) != gated.end();
    };
    std::map<std::string, std::vector<double>> own;         // category -> evidence
    std::map<std::string, std::vector<double>> ownScore;    // the classifier's probability of it
    std::map<std::string, std::vector<double>> distractor;  // category -> evidence
    sagrid::app::ProgressBar bar("evidence", samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      bar.update(i);
      const auto& s = samples[i];
      const std::string cls = sagrid::categoryClass(s.category);
      try {
        if (cls != sagrid::kRejectedCategory) {
          if (isGated(cls)) {
            own[cls].push_back(evidence(s, cls));
            const auto decision = classifier.classify(s);
            ownScore[cls].push_back(decision.category == cls ? decision.score : 0.0);
          }
        } else {
          for (const auto& category : gated) distractor[category].push_back(evidence(s, category));
        }
      } catch (const sagrid::Error& e) {
        std::fprintf(stderr, "%s: skipped: %s\n", s.id.c_str(), e.what());
      }
    }
    bar.finish();
    auto gate = sagrid::fitEvidenceGate(own, o->keep, models);
    if (o->sureAbove > 0) gate.sureProbability = o->sureAbove;
    std::string command = "sagrid category evidence";
    for (const auto& d : o->data) command += " --data " + d;
    if (!o->up.empty()) command += " --up " + o->up;
    for (const auto& c : o->gated) command += " --category " + c;
    command += " --keep " + std::to_string(o->keep) + " --models " + dir.string();
    if (gate.sureProbability) command += " --sure-above " + std::to_string(*gate.sureProbability);
    gate.record["data"] = o->data;
    gate.record["command"] = command;
    std::cout << "| category | objects | threshold | kept | kept with the classifier sure | "
                 "distractors | distractors below |\n"
                 "|---|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& [category, threshold] : gate.thresholds) {
      const auto& values = own.at(category);
      const auto& scores = ownScore.at(category);
      const auto kept = std::count_if(values.begin(), values.end(),
                                      [&, t = threshold](double v) { return v >= t; });
      long keptOrSure = 0;
      for (std::size_t i = 0; i < values.size(); ++i)
        keptOrSure += values[i] >= threshold || !gate.asks(scores[i]);
      const auto& others = distractor[category];
      const auto below =
          std::count_if(others.begin(), others.end(), [t = threshold](double v) { return v < t; });
      gate.record["kept"][category] = kept;
      gate.record["kept_with_sure"][category] = keptOrSure;
      gate.record["distractors_below"][category] = {below, others.size()};
      std::printf("| %s | %zu | %.4f | %ld | %ld | %zu | %ld |\n", category.c_str(), values.size(),
                  threshold, static_cast<long>(kept), keptOrSure, others.size(),
                  static_cast<long>(below));
    }
    classifier.evidence = gate;
    classifier.save(file);
    std::fprintf(stderr, "wrote the evidence gate into %s\n", file.string().c_str());
  });

  auto* split = cmd->add_subcommand(
      "split", "Split a dataset folder's ids deterministically: 2/3 train, 1/3 val (by sha256 of the id).");
  split->add_option("--data", o->data, "Dataset folder (repeat for several: one split of all ids)")->required();
  split->add_option("--out", o->splitOut, "Split file to write (JSON)")->required();
  split->callback([o] {
    std::vector<std::string> ids;
    std::string source;
    for (const auto& dir : o->data) {
      for (const auto& e : sagrid::readDataset(dir)) ids.push_back(e.id);
      source += (source.empty() ? "" : ", ") + fs::path(dir).filename().string();
    }
    const auto s = sagrid::splitIds(ids);
    sagrid::writeIdSplit(s, o->splitOut, source);
    std::fprintf(stderr, "wrote %s: %zu train, %zu val\n", o->splitOut.c_str(), s.train.size(), s.val.size());
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("category", setupCategory);
