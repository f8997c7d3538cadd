#include "core/annotate/category_update.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/annotate/category_training.h"
#include "core/common/error.h"
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

void requireSeveralClasses(const std::vector<CategorySample>& heldOut) {
  std::set<std::string> classes;
  for (const auto& s : heldOut) classes.insert(categoryClass(s.category));
  if (classes.size() >= 2) return;
  throw InvalidArgument(
      "the held-out folders hold " +
      (classes.empty() ? std::string("no object") : "only " + *classes.begin() + " objects") +
      ": a classifier that calls everything one class would look best there; give held-out "
      "objects of at least two of stove, sink and look-alike (none). Nothing was written; the "
      "current classifier stays");
}

CategoryVerdict judgeCategoryUpdate(const CategoryClassifier& candidate, const fs::path& currentFile,
                                    const std::vector<WeightedFolder>& heldOut,
                                    const FeatureOptions& features) {
  // The held-out inputs, once per input set (with or without the top relief, the parts).
  std::map<CategoryInputSet, std::vector<CategorySample>> samplesByInputs;
  const auto shareRight = [&](const CategoryClassifier& c) {
    auto found = samplesByInputs.find(c.inputSet());
    if (found == samplesByInputs.end()) {
      auto samples = collectWeightedSamples(heldOut, features, {}, c.inputSet());
      requireSeveralClasses(samples);
      found = samplesByInputs.emplace(c.inputSet(), std::move(samples)).first;
    }
    return balancedShareRight(evaluateCategories(
        [&](const CategorySample& s) { return c.classify(s.descriptor); }, found->second));
  };
  CategoryVerdict verdict;
  verdict.after = shareRight(candidate);
  std::error_code ec;
  if (fs::exists(currentFile, ec)) verdict.before = shareRight(CategoryClassifier::load(currentFile));
  verdict.adopted = !verdict.before || verdict.after > *verdict.before;
  char line[200];
  char was[32] = "(none)";
  if (verdict.before) std::snprintf(was, sizeof was, "%.1f %%", 100 * *verdict.before);
  std::snprintf(line, sizeof line,
                "category classifier: share right %s -> %.1f %% on the held-out objects: %s", was,
                100 * verdict.after,
                verdict.adopted ? "adopted" : "refused, current classifier kept");
  verdict.reason = line;
  return verdict;
}

void recordCategoryVerdict(const CategoryVerdict& verdict, const fs::path& modelsDir,
                           const std::vector<std::string>& heldOut) {
  nlohmann::json line = {{"model", "category"},
                         {"held_out", heldOut},
                         {"adopted", verdict.adopted},
                         {"candidate_share_right", verdict.after},
                         {"time", currentUtcTimestamp()}};
  if (verdict.before) line["current_share_right"] = *verdict.before;
  fs::create_directories(modelsDir);
  std::ofstream(modelsDir / "guard.jsonl", std::ios::app) << line.dump() << "\n";
}

CategoryClassifier retrainCategoryClassifier(const CategoryClassifier& current,
                                             const fs::path& curated, double curatedWeight,
                                             const FeatureOptions& features,
                                             std::vector<std::string>& missing,
                                             const FolderProgress& onProgress) {
  const nlohmann::json& record = current.training;
  std::vector<WeightedFolder> folders;
  std::vector<std::string> data;
  if (record.contains("data") && record["data"].is_array()) {
    for (const auto& entry : record["data"]) {
      if (!entry.is_string()) continue;
      const WeightedFolder folder = parseWeightedFolder(entry.get<std::string>());
      std::error_code ec;
      if (fs::is_directory(folder.dir, ec)) {
        folders.push_back(folder);
        data.push_back(entry.get<std::string>());
      } else {
        missing.push_back(folder.dir.string());
      }
    }
  }
  folders.push_back({curated, curatedWeight});
  char weighted[32];
  std::snprintf(weighted, sizeof weighted, "@%g", curatedWeight);
  data.push_back(curated.string() + weighted);

  CategoryTrainingOptions options;
  options.l2 = record.value("l2", options.l2);
  options.iterations = record.value("iterations", options.iterations);
  options.quadratic = record.value("quadratic", options.quadratic);
  options.threshold = current.threshold();
  options.inputs = current.inputSet();
  if (record.contains("trees")) {  // the same kind of classifier as the current one
    options.trees = true;
    options.boosting.rounds = record.at("trees").value("rounds", options.boosting.rounds);
    options.boosting.depth = record.at("trees").value("depth", options.boosting.depth);
    options.boosting.rowShare = record.at("trees").value("row_share", options.boosting.rowShare);
    options.boosting.featureShare =
        record.at("trees").value("feature_share", options.boosting.featureShare);
    options.boosting.seed = record.at("trees").value("seed", options.boosting.seed);
  }
  const auto samples = collectWeightedSamples(folders, features, {}, options.inputs, onProgress);
  if (samples.empty())
    throw InvalidArgument("no object to retrain the category classifier on: " + curated.string() +
                          " holds none and the classifier's own training folders are missing");
  CategoryClassifier candidate = CategoryClassifier::train(samples, options);
  candidate.featureBackend = current.featureBackend;
  candidate.featureConfigHash = current.featureConfigHash;
  candidate.gridResolution = current.gridResolution;
  candidate.evidence = current.evidence;
  candidate.training["data"] = data;
  candidate.training["retrained_from"] = record.value("command", std::string());
  candidate.training["missing_data"] = missing;
  return candidate;
}

}  // namespace sagrid
