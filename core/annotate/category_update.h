// Updating the category classifier from curated data, guarded: a candidate trained on dataset
// folders replaces the current classifier only where its share right on curated objects it did
// not train on (averaged over stoves, sinks and look-alikes) is higher by more than the standard
// error of the per-object differences (pairedCategoryChange); otherwise the current one stays.
// Judged on held-out folders, or leaving one source of the curated objects out at a time. `sagrid
// category train --guard|--guard-by-source` and the GUI's Train panel ("Retrain the category
// classifier", after the curator confirmed or switched categories) both go through here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/annotate/category_classifier.h"
#include "core/common/error.h"
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
// Its inverse: "DIR", or "DIR@W" for a weight other than 1.
std::string weightedFolderText(const WeightedFolder& folder);

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
// score best there. Throws InvalidArgument naming `what` (the folders the samples came from) and
// saying nothing was written, for fewer than two classes.
void requireSeveralClasses(const std::vector<CategorySample>& samples,
                           const std::string& what = "the held-out folders");

struct CategoryVerdict {
  bool adopted = false;
  std::optional<double> before;  // the current classifier's share right; none without one
  double after = 0;              // the candidate's
  // The standard error of the difference of the two (paired by object); NaN without a current
  // classifier or where a class has one object.
  double noise = NAN;
  std::string reason;            // one line: both figures and the decision
  // Judged leaving one source out (judgeCategoryUpdateBySource): over how many sources; 0 when
  // judged on held-out folders.
  std::size_t sources = 0;
};

// Judges `candidate` against the classifier in `currentFile` (none there: adopted) on the objects
// of `heldOut`: adopted only when its share right, averaged over the classes, is higher by more
// than its noise.
CategoryVerdict judgeCategoryUpdate(const CategoryClassifier& candidate,
                                    const std::filesystem::path& currentFile,
                                    const std::vector<WeightedFolder>& heldOut,
                                    const FeatureOptions& features);

// Appends the verdict as one JSON line to `modelsDir`/guard.jsonl (the same log as the models'),
// naming the folders it was judged on (held out, or left out by source).
void recordCategoryVerdict(const CategoryVerdict& verdict, const std::filesystem::path& modelsDir,
                           const std::vector<std::string>& judgedOn);

// What a classifier is trained from: its weighted folders and its settings.
struct CategoryRecipe {
  std::vector<WeightedFolder> folders;
  CategoryTrainingOptions options;
};

// The recipe a saved classifier records (its training record's "data" and settings: threshold,
// l2, iterations, quadratic inputs, top relief, part statistics, trees); folders of the record
// that are not on this machine are left out and listed in `missing`.
CategoryRecipe recipeOf(const CategoryClassifier& classifier, std::vector<std::string>& missing);

// `recipe` with `curated` among its folders: in place of an entry naming the same folder (a
// classifier retrained twice on one curated set counts it once), else last.
CategoryRecipe withCuratedFolder(CategoryRecipe recipe, const WeightedFolder& curated);

// Thrown by judgeCategoryUpdateBySource when the curated objects come from fewer than two sources:
// none can be left out while another teaches (the GUI then retrains unguarded and says so).
class TooFewSources : public InvalidArgument {
 public:
  using InvalidArgument::InvalidArgument;
};

// Called before each fold's training while a recipe is judged by source: which recipe
// ("candidate" or "current"), the fold and the number of folds.
using RecipeFoldProgress = std::function<void(const std::string& recipe, int fold, int folds)>;

// The guard judged leaving one source out, for curated objects that are training data too (a
// held-out folder would take them from training). Each source of the `curated` folders' objects
// (core/dataset/object_source.h) is decided by the candidate recipe trained without that source:
// on its other folders plus the curated objects of the other sources, at the weight the recipe
// gives their folder (a curated folder the recipe does not list is judged, never trained on).
// The current classifier is judged the same way through its recorded recipe (recipeOf) when every
// folder of that is here; otherwise as it is, on every curated object (should it have trained on
// some, the comparison favours it: the guard errs towards keeping it), and the reason says so.
// The candidate is adopted when its share right, averaged over stoves, sinks and look-alikes, is
// higher by more than its noise. Throws InvalidArgument (saying the current classifier stays) for
// curated objects of fewer than two classes, TooFewSources for fewer than two sources.
CategoryVerdict judgeCategoryUpdateBySource(const CategoryRecipe& candidate,
                                            const CategoryClassifier& current,
                                            const std::vector<std::filesystem::path>& curated,
                                            const FeatureOptions& features,
                                            const FolderProgress& onProgress = {},
                                            const RecipeFoldProgress& onFold = {});

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
