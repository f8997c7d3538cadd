// Updating the category classifier from curated data, guarded: a candidate trained on dataset
// folders replaces the current classifier only where its share right on held-out curated objects
// (averaged over stoves, sinks and look-alikes) is higher; otherwise the current one stays.
// `sagrid category train --guard` and the GUI's Train panel ("Retrain the category classifier",
// after the curator confirmed or switched categories) both go through here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/annotate/category_classifier.h"
#include "core/features/feature_pipeline.h"

namespace sagrid {

// A dataset folder and how many times its objects count ("DIR@W": a few real objects among many
// generated ones).
struct WeightedFolder {
  std::filesystem::path dir;
  double weight = 1.0;
};
// "DIR" or "DIR@W"; throws InvalidArgument naming `text` for a weight that is not a number.
WeightedFolder parseWeightedFolder(const std::string& text);

// Called per object of each folder while its descriptors are computed.
using FolderProgress =
    std::function<void(const std::filesystem::path& dir, std::size_t done, std::size_t total)>;

// Descriptors of every folder's objects but `exclude`, each weighted as its folder; objects whose
// features failed are skipped and counted per folder in `skipped` (when given).
std::vector<CategorySample> collectWeightedSamples(
    const std::vector<WeightedFolder>& folders, const FeatureOptions& features,
    const std::set<std::string>& exclude, const CategoryInputSet& inputs,
    const FolderProgress& onProgress = {},
    std::vector<std::size_t>* skipped = nullptr);

// A guard set of one class cannot judge a classifier: one that calls everything that class would
// score best there. Throws InvalidArgument (saying nothing was written) for fewer than two classes.
void requireSeveralClasses(const std::vector<CategorySample>& heldOut);

struct CategoryVerdict {
  bool adopted = false;
  std::optional<double> before;  // the current classifier's share right; none without one
  double after = 0;              // the candidate's
  std::string reason;            // one line: both figures and the decision
};

// Judges `candidate` against the classifier in `currentFile` (none there: adopted) on the objects
// of `heldOut`: adopted only when its share right, averaged over the classes, is higher.
CategoryVerdict judgeCategoryUpdate(const CategoryClassifier& candidate,
                                    const std::filesystem::path& currentFile,
                                    const std::vector<WeightedFolder>& heldOut,
                                    const FeatureOptions& features);

// Appends the verdict as one JSON line to `modelsDir`/guard.jsonl (the same log as the models').
void recordCategoryVerdict(const CategoryVerdict& verdict, const std::filesystem::path& modelsDir,
                           const std::vector<std::string>& heldOut);

// Curated objects count this many times among the generated ones when the classifier is
// retrained (as the shipped classifier weighs its real objects: resources/models/category.json).
inline constexpr double kCuratedCategoryWeight = 3.0;

// The classifier `current` retrained with curated objects: on the folders it was trained on that
// still exist here (its training record's "data") and `curated` (weighted `curatedWeight`, as the
// shipped classifier weighs real objects), with its own settings (threshold, l2, iterations,
// quadratic inputs, top relief, evidence gate). Folders of the record that are missing are listed
// in `missing`. Throws InvalidArgument when no object is left to train on.
CategoryClassifier retrainCategoryClassifier(const CategoryClassifier& current,
                                             const std::filesystem::path& curated,
                                             double curatedWeight, const FeatureOptions& features,
                                             std::vector<std::string>& missing,
                                             const FolderProgress& onProgress = {});

}  // namespace sagrid
