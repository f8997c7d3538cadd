// K-fold cross-validation of the category classifier (category_classifier.h) over a few real
// objects: a 2/3 - 1/3 split of 52 real objects leaves 3 real stoves to judge it by, where one
// object moves a share by 33 points. Every real object is decided once, by the classifier trained
// without its fold (on the always-used samples, e.g. the generated ones, plus the other folds).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/annotate/category_classifier.h"
#include "core/annotate/category_training.h"

namespace sagrid {

// What follows the classifier's decision on a sample (the evidence gate), or nothing.
using CategoryCheck =
    std::function<CategoryDecision(const CategorySample&, const CategoryDecision&)>;

// Each fold of `validated` decided by a classifier trained with `options` on `always` plus the
// other folds (then by `check` when given); the folds' evaluations summed (misses in fold order).
// `onFold(k, folds)` before each fold's training. A validated sample of weight 0 is decided but
// never trained on (objects a recipe does not learn from, judged all the same). Throws
// InvalidArgument when folds < 2 or there are fewer validated samples than folds, or when an id
// appears twice among them.
CategoryEvaluation crossValidateCategories(const std::vector<CategorySample>& always,
                                           const std::vector<CategorySample>& validated, int folds,
                                           const CategoryTrainingOptions& options,
                                           const std::function<void(int, int)>& onFold = {},
                                           const CategoryCheck& check = {});

// Leave one source out: each source of `validated` (CategorySample::source) is a fold, decided by
// a classifier that saw no object of it. Throws InvalidArgument for fewer than two sources.
CategoryEvaluation crossValidateCategoriesBySource(const std::vector<CategorySample>& always,
                                                   const std::vector<CategorySample>& validated,
                                                   const CategoryTrainingOptions& options,
                                                   const std::function<void(int, int)>& onFold = {},
                                                   const CategoryCheck& check = {});

}  // namespace sagrid
