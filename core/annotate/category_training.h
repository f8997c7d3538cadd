// Data for the category classifier (category_classifier.h): object descriptors of labelled dataset
// folders through the feature pipeline and its per-dataset cache (DIR/.sagrid-cache), a
// deterministic train/val split of a folder's ids written to a file, and the evaluation table
// (share right on stoves, on sinks, share of distractors rejected).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/annotate/category_classifier.h"
#include "core/common/paired_change.h"
#include "core/features/feature_pipeline.h"

namespace sagrid {

// Descriptors of every object of a dataset folder whose id is not in `excludeIds`. The group of a
// sample is the folder's name, plus the generator kind for generated distractors. An object's
// labels.json up axis overrides features.up; objects without labels.json take the manifest's
// category and features.up. Objects whose features fail are skipped and counted in `failed` (when
// given). A sample's descriptor is categoryInputs(features, mesh, inputs): the descriptor, then
// what `inputs` asks for (the relief of the object's top, the statistics of its mesh's parts).
// Samples keep their mesh, labelled up axis, feature cache and the words of the mesh file's name
// (a name the classifier learns from where the labels hold the file's sha256 and no generator).
std::vector<CategorySample> collectCategorySamples(
    const std::filesystem::path& dataDir, const FeatureOptions& features,
    const std::set<std::string>& excludeIds = {},
    const std::function<void(std::size_t, std::size_t, const std::string&)>& onProgress = {},
    std::size_t* failed = nullptr, const CategoryInputSet& inputs = {});

// Fold of each id (0 .. folds-1): ids ordered by the sha256 of the id, the i-th to fold i % folds,
// so folds differ in size by one at most and do not depend on the order given. Throws
// InvalidArgument when folds < 1.
std::map<std::string, int> assignFolds(const std::vector<std::string>& ids, int folds);

// A split of object ids into "train" and "val".
struct IdSplit {
  std::set<std::string> train, val;
};
// Deterministic: ids ordered by the sha256 of the id, every third to val (1/3: fold 2 of
// assignFolds(ids, 3)), the rest train.
IdSplit splitIds(const std::vector<std::string>& ids);
// JSON {"train": [...], "val": [...], "rule": "..."}; readIdSplit throws FileError naming the file.
void writeIdSplit(const IdSplit& split, const std::filesystem::path& file, const std::string& source);
IdSplit readIdSplit(const std::filesystem::path& file);

struct CategoryEvaluation {
  struct Count {
    int total = 0, right = 0;
  };
  // By true class ("stove", "sink", "none"): right = predicted category equals it ("none" =
  // rejected).
  std::map<std::string, Count> byClass;
  // By sample group (dataset folder / distractor kind) and true class.
  std::map<std::string, Count> byGroup;
  std::map<std::string, std::map<std::string, int>> confusion;  // true -> predicted -> count
  // Every object decided wrongly, in sample order (what a curator looks at first).
  struct Miss {
    std::string id, group, truth, predicted;
    double score = 0;  // the decision's score (probability of its best known category)
    std::string best;  // that best known category
  };
  std::vector<Miss> misses;
};

// `decide` is the classifier under test (a CategoryClassifier at a threshold, or ModelSet's
// decideCategory for retrieval without a classifier, perhaps followed by the evidence gate).
CategoryEvaluation evaluateCategories(
    const std::function<CategoryDecision(const CategorySample&)>& decide,
    const std::vector<CategorySample>& samples);

// The mean over the true classes of the share decided right: stoves, sinks and look-alikes count
// alike however many of each there are (the guard on classifier updates compares it). 0 when empty.
double balancedShareRight(const CategoryEvaluation& evaluation);

// Two classifiers decided the same objects: per true class, each object's figure is 1 where it was
// decided wrongly (objects matched by group and id), the classes counting alike, so 1 - the means
// are the balanced shares right and the guard adopts the candidate only where its share is higher
// by more than the standard error of the per-object differences (PairedChange::clearlyBetter).
PairedChange pairedCategoryChange(const CategoryEvaluation& current,
                                  const CategoryEvaluation& candidate);

// Markdown: the per-class table (stoves right, sinks right, distractors rejected), per group, the
// confusion matrix and the list of objects decided wrongly.
std::string categoryEvaluationTable(const CategoryEvaluation& evaluation);

}  // namespace sagrid
