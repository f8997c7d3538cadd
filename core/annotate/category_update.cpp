#include "core/annotate/category_update.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "core/annotate/category_cross_validation.h"
#include "core/annotate/category_training.h"
#include "core/common/error.h"
#include "core/common/report_cell.h"
#include "core/labels/labels.h"

namespace sagrid {

namespace fs = std::filesystem;

WeightedFolder parseWeightedFolder(const std::string& text) {
  const auto at = text.rfind('@');
  if (at == std::string::npos) return {text, 1.0};
  try {
    std::size_t used = 0;
    const std::string weight = text.substr(at + 1);
    const double w = std::stod(weight, &used);
    if (used != weight.size() || !(w > 0)) throw std::invalid_argument(weight);
    return {text.substr(0, at), w};
  } catch (const std::exception&) {
    throw InvalidArgument(text + ": expected DIR or DIR@WEIGHT (a positive number)");
  }
}

std::vector<CategorySample> collectWeightedSamples(const std::vector<WeightedFolder>& folders,
                                                   const FeatureOptions& features,
                                                   const std::set<std::string>& exclude,
                                                   const CategoryInputSet& inputs,
                                                   const FolderProgress& onProgress,
                                                   std::vector<std::size_t>* skipped) {
  std::vector<CategorySample> all;
  if (skipped) skipped->assign(folders.size(), 0);
  for (std::size_t f = 0; f < folders.size(); ++f) {
    const WeightedFolder& folder = folders[f];
    std::size_t failed = 0;
    auto samples = collectCategorySamples(
        folder.dir, features, exclude,
        [&](std::size_t done, std::size_t total, const std::string&) {
          if (onProgress) onProgress(folder.dir, done, total);
        },
        &failed, inputs);
    if (skipped) (*skipped)[f] = failed;
    for (auto& s : samples) s.weight = folder.weight;
    all.insert(all.end(), samples.begin(), samples.end());
  }
  return all;
}

void requireSeveralClasses(const std::vector<CategorySample>& samples, const std::string& what) {
  std::set<std::string> classes;
  for (const auto& s : samples) classes.insert(categoryClass(s.category));
  if (classes.size() >= 2) return;
  throw InvalidArgument(
      what + " hold " +
      (classes.empty() ? std::string("no object") : "only " + *classes.begin() + " objects") +
      ": a classifier that calls everything one class would look best there; give "
      "objects of at least two of stove, sink and look-alike (none). Nothing was written; the "
      "current classifier stays");
}

namespace {

// "stoves 17/26 -> 21/26, sinks 42/45, look-alikes 84/97 -> 85/97": each class's objects right,
// before (when there is a current classifier) and after.
std::string classFigures(const std::optional<CategoryEvaluation>& before,
                         const CategoryEvaluation& after) {
  std::string text;
  for (const auto& [cls, name] : {std::pair<const char*, const char*>{"stove", "stoves"},
                                  {"sink", "sinks"},
                                  {kRejectedCategory, "look-alikes"}}) {
    const std::string key = cls;  // a lambda may not capture a structured binding (C++17)
    const auto count = [&](const CategoryEvaluation& ev) {
      const auto it = ev.byClass.find(key);
      return it == ev.byClass.end() ? CategoryEvaluation::Count{} : it->second;
    };
    const CategoryEvaluation::Count a = count(after);
    if (a.total == 0) continue;
    const auto fraction = [](const CategoryEvaluation::Count& c) {
      return std::to_string(c.right) + "/" + std::to_string(c.total);
    };
    text += (text.empty() ? "" : ", ") + std::string(name) + " " +
            (before && count(*before).total ? fraction(count(*before)) + " -> " : std::string()) +
            fraction(a);
  }
  return text;
}

// The verdict on the candidate's evaluation `after` against the current classifier's `before`
// (none: adopted): adopted when the share right averaged over the classes is higher by more than
// its noise (the two paired by object); the reason names both shares, the noise, each class's
// figures and `judgedOn` (where they were measured).
CategoryVerdict decide(const std::optional<CategoryEvaluation>& before,
                       const CategoryEvaluation& after, const std::string& judgedOn) {
  CategoryVerdict verdict;
  verdict.after = balancedShareRight(after);
  std::string decision = "adopted";
  if (before) {
    verdict.before = balancedShareRight(*before);
    const PairedChange change = pairedCategoryChange(*before, after);
    verdict.noise = change.noise;
    verdict.adopted = change.clearlyBetter();
    if (!verdict.adopted) decision = change.verdict() + ", current classifier kept";
  } else {
    verdict.adopted = true;
  }
  char was[32] = "(none)";
  if (verdict.before) std::snprintf(was, sizeof was, "%.1f %%", 100 * *verdict.before);
  char figures[96];
  std::snprintf(figures, sizeof figures, "%s -> %.1f %%", was, 100 * verdict.after);
  const std::string noise =
      verdict.before ? " (noise " + reportCell(100 * verdict.noise, "%.1f %%") + ")" : "";
  verdict.reason = std::string("category classifier: share right ") + figures + noise + " (" +
                   classFigures(before, after) + ") " + judgedOn + ": " + decision;
  return verdict;
}

// A folder's identity however it is spelled (relative, through links).
std::string folderKey(const fs::path& dir) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(dir), ec);
  return (ec ? dir.lexically_normal() : canonical).string();
}

bool sameFolder(const fs::path& a, const fs::path& b) { return folderKey(a) == folderKey(b); }

// Descriptors of weighted folders, each folder read once per input set however often the guard
// asks: both recipes share most of their folders and all the curated ones.
class FolderSamples {
 public:
  FolderSamples(const FeatureOptions& features, const FolderProgress& onProgress)
      : m_features(features), m_onProgress(onProgress) {}
  std::vector<CategorySample> operator()(const std::vector<WeightedFolder>& folders,
                                         const CategoryInputSet& inputs) {
    std::vector<CategorySample> all;
    for (const WeightedFolder& folder : folders) {
      auto key = std::make_pair(folderKey(folder.dir), inputs);
      auto read = m_read.find(key);
      if (read == m_read.end())
        read = m_read
                   .emplace(std::move(key), collectWeightedSamples({{folder.dir, 1.0}}, m_features,
                                                                   {}, inputs, m_onProgress))
                   .first;
      for (CategorySample s : read->second) {
        s.weight = folder.weight;
        all.push_back(std::move(s));
      }
    }
    return all;
  }

 private:
  const FeatureOptions& m_features;
  const FolderProgress& m_onProgress;
  std::map<std::pair<std::string, CategoryInputSet>, std::vector<CategorySample>> m_read;
};

// "A, B" of the folders.
std::string folderList(const std::vector<fs::path>& folders) {
  std::string list;
  for (const auto& dir : folders) list += (list.empty() ? "" : ", ") + dir.string();
  return list;
}

// `recipe` cross-validated over the sources of the `curated` folders' objects: its evaluation
// over every curated object, and how many sources it was measured on.
struct SourceFigures {
  CategoryEvaluation evaluation;
  std::size_t objects = 0, sources = 0;
};
SourceFigures shareRightBySource(const CategoryRecipe& recipe, const std::vector<fs::path>& curated,
                                 FolderSamples& samplesOf,
                                 const std::function<void(int, int)>& onFold) {
  std::vector<WeightedFolder> always, judged;
  for (const auto& dir : curated) judged.push_back({dir, 0.0});
  for (const auto& folder : recipe.folders) {
    const auto same = std::find_if(judged.begin(), judged.end(), [&](const WeightedFolder& j) {
      return sameFolder(j.dir, folder.dir);
    });
    if (same != judged.end())
      same->weight = folder.weight;
    else
      always.push_back(folder);
  }
  const auto judgedSamples = samplesOf(judged, recipe.options.inputs);
  requireSeveralClasses(judgedSamples, folderList(curated));
  std::set<std::string> sources;
  for (const auto& s : judgedSamples) sources.insert(s.source);
  if (sources.size() < 2)
    throw TooFewSources("the curated objects of " + folderList(curated) + " come from " +
                        (sources.empty() ? std::string("no source")
                                         : "one source only (" + *sources.begin() + ")") +
                        ": leaving one source out needs at least two; give held-out objects of "
                        "other sources instead. Nothing was written; the current classifier stays");
  const auto alwaysSamples = samplesOf(always, recipe.options.inputs);
  const CategoryEvaluation ev =
      crossValidateCategoriesBySource(alwaysSamples, judgedSamples, recipe.options, onFold);
  return {ev, judgedSamples.size(), sources.size()};
}

}  // namespace

CategoryVerdict judgeCategoryUpdate(const CategoryClassifier& candidate, const fs::path& currentFile,
                                    const std::vector<WeightedFolder>& heldOut,
                                    const FeatureOptions& features) {
  // The held-out inputs, once per input set (with or without the top relief, the parts).
  std::map<CategoryInputSet, std::vector<CategorySample>> samplesByInputs;
  const auto evaluate = [&](const CategoryClassifier& c) {
    auto found = samplesByInputs.find(c.inputSet());
    if (found == samplesByInputs.end()) {
      auto samples = collectWeightedSamples(heldOut, features, {}, c.inputSet());
      requireSeveralClasses(samples);
      found = samplesByInputs.emplace(c.inputSet(), std::move(samples)).first;
    }
    return evaluateCategories([&](const CategorySample& s) { return c.classify(s); },
                              found->second);
  };
  const CategoryEvaluation after = evaluate(candidate);
  std::optional<CategoryEvaluation> before;
  std::error_code ec;
  if (fs::exists(currentFile, ec)) before = evaluate(CategoryClassifier::load(currentFile));
  return decide(before, after, "on the held-out objects");
}

void recordCategoryVerdict(const CategoryVerdict& verdict, const fs::path& modelsDir,
                           const std::vector<std::string>& judgedOn) {
  nlohmann::json line = {
      {"model", "category"},        {verdict.sources ? "judged_by_source" : "held_out", judgedOn},
      {"adopted", verdict.adopted}, {"candidate_share_right", verdict.after},
      {"reason", verdict.reason},   {"time", currentUtcTimestamp()}};
  if (verdict.before) line["current_share_right"] = *verdict.before;
  if (std::isfinite(verdict.noise)) line["paired_noise"] = verdict.noise;
  if (verdict.sources) line["sources"] = verdict.sources;
  fs::create_directories(modelsDir);
  std::ofstream(modelsDir / "guard.jsonl", std::ios::app) << line.dump() << "\n";
}

CategoryRecipe recipeOf(const CategoryClassifier& classifier, std::vector<std::string>& missing) {
  const nlohmann::json& record = classifier.training;
  CategoryRecipe recipe;
  if (record.contains("data") && record["data"].is_array()) {
    for (const auto& entry : record["data"]) {
      if (!entry.is_string()) continue;
      const WeightedFolder folder = parseWeightedFolder(entry.get<std::string>());
      std::error_code ec;
      if (fs::is_directory(folder.dir, ec))
        recipe.folders.push_back(folder);
      else
        missing.push_back(folder.dir.string());
    }
  }
  CategoryTrainingOptions& options = recipe.options;
  options.l2 = record.value("l2", options.l2);
  options.iterations = record.value("iterations", options.iterations);
  options.quadratic = record.value("quadratic", options.quadratic);
  options.threshold = classifier.threshold();
  options.inputs = classifier.inputSet();
  // A weight that was fixed stays fixed; a file that read names before the weight was learned
  // (session 66) read them by the Bayes rule.
  if (options.inputs.fileName) {
    const nlohmann::json weight = record.value("file_name_weight", nlohmann::json::object());
    if (weight.value("fixed", false))
      options.nameWeight = weight.value("weight", 1.0);
    else if (!record.contains("file_name_weight"))
      options.nameWeight = 1.0;
  }
  if (record.contains("trees")) {  // the same kind of classifier
    const nlohmann::json& trees = record.at("trees");
    options.trees = true;
    options.boosting.rounds = trees.value("rounds", options.boosting.rounds);
    options.boosting.depth = trees.value("depth", options.boosting.depth);
    options.boosting.rowShare = trees.value("row_share", options.boosting.rowShare);
    options.boosting.featureShare = trees.value("feature_share", options.boosting.featureShare);
    options.boosting.seed = trees.value("seed", options.boosting.seed);
  }
  return recipe;
}

std::string weightedFolderText(const WeightedFolder& folder) {
  if (folder.weight == 1.0) return folder.dir.string();
  char weighted[32];
  std::snprintf(weighted, sizeof weighted, "@%g", folder.weight);
  return folder.dir.string() + weighted;
}

CategoryRecipe withCuratedFolder(CategoryRecipe recipe, const WeightedFolder& curated) {
  auto& folders = recipe.folders;
  folders.erase(
      std::remove_if(folders.begin(), folders.end(),
                     [&](const WeightedFolder& f) { return sameFolder(f.dir, curated.dir); }),
      folders.end());
  folders.push_back(curated);
  return recipe;
}

CategoryVerdict judgeCategoryUpdateBySource(const CategoryRecipe& candidate,
                                            const CategoryClassifier& current,
                                            const std::vector<fs::path>& curated,
                                            const FeatureOptions& features,
                                            const FolderProgress& onProgress,
                                            const RecipeFoldProgress& onFold) {
  FolderSamples samplesOf(features, onProgress);
  const auto figures = [&](const CategoryRecipe& recipe, const std::string& name) {
    return shareRightBySource(recipe, curated, samplesOf, [&](int k, int folds) {
      if (onFold) onFold(name, k, folds);
    });
  };
  const SourceFigures after = figures(candidate, "candidate");
  std::vector<std::string> missing;
  const CategoryRecipe recorded = recipeOf(current, missing);
  std::string how = "on " + std::to_string(after.objects) + " curated objects, each source of " +
                    std::to_string(after.sources) + " left out of training in turn";
  CategoryEvaluation before;
  if (missing.empty() && !recorded.folders.empty()) {
    before = figures(recorded, "current").evaluation;
  } else {
    std::vector<WeightedFolder> judged;
    for (const auto& dir : curated) judged.push_back({dir, 1.0});
    const auto samples = samplesOf(judged, current.inputSet());
    before =
        evaluateCategories([&](const CategorySample& s) { return current.classify(s); }, samples);
    how += " (the current classifier as it is: " +
           (missing.empty()
                ? std::string("it records no training folders")
                : std::to_string(missing.size()) + " of its training folders are not here") +
           ")";
  }
  CategoryVerdict verdict = decide(before, after.evaluation, how);
  verdict.sources = after.sources;
  return verdict;
}

CategoryClassifier retrainCategoryClassifier(const CategoryClassifier& current,
                                             const fs::path& curated, double curatedWeight,
                                             const FeatureOptions& features,
                                             std::vector<std::string>& missing,
                                             const FolderProgress& onProgress) {
  CategoryRecipe recipe = withCuratedFolder(recipeOf(current, missing), {curated, curatedWeight});
  const auto samples =
      collectWeightedSamples(recipe.folders, features, {}, recipe.options.inputs, onProgress);
  if (samples.empty())
    throw InvalidArgument("no object to retrain the category classifier on: " + curated.string() +
                          " holds none and the classifier's own training folders are missing");
  CategoryClassifier candidate = CategoryClassifier::train(samples, recipe.options);
  candidate.featureBackend = current.featureBackend;
  candidate.featureConfigHash = current.featureConfigHash;
  candidate.gridResolution = current.gridResolution;
  candidate.evidence = current.evidence;
  std::vector<std::string> data;
  for (const auto& folder : recipe.folders) data.push_back(weightedFolderText(folder));
  candidate.training["data"] = data;
  candidate.training["retrained_from"] = current.training.value("command", std::string());
  candidate.training["missing_data"] = missing;
  return candidate;
}

}  // namespace sagrid
