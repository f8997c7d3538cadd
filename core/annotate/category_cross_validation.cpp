#include "core/annotate/category_cross_validation.h"

#include <map>
#include <set>

#include "core/common/error.h"

namespace sagrid {

namespace {
void add(CategoryEvaluation& total, const CategoryEvaluation& part) {
  for (const auto& [name, c] : part.byClass)
    total.byClass[name].total += c.total, total.byClass[name].right += c.right;
  for (const auto& [name, c] : part.byGroup)
    total.byGroup[name].total += c.total, total.byGroup[name].right += c.right;
  for (const auto& [truth, predicted] : part.confusion)
    for (const auto& [category, n] : predicted) total.confusion[truth][category] += n;
  total.misses.insert(total.misses.end(), part.misses.begin(), part.misses.end());
}
// Each fold k of `validated` (fold.at(id)) decided by a classifier trained without it.
CategoryEvaluation crossValidate(const std::vector<CategorySample>& always, const std::vector<CategorySample>& validated,
                                 const std::map<std::string, int>& fold, int folds,
                                 const CategoryTrainingOptions& options, const std::function<void(int, int)>& onFold,
                                 const CategoryCheck& check) {
  CategoryEvaluation total;
  for (int k = 0; k < folds; ++k) {
    if (onFold) onFold(k, folds);
    std::vector<CategorySample> train = always, held;
    for (const auto& s : validated) {
      if (fold.at(s.id) == k)
        held.push_back(s);
      else if (s.weight > 0)
        train.push_back(s);
    }
    const auto classifier = CategoryClassifier::train(train, options);
    add(total, evaluateCategories(
                   [&](const CategorySample& s) {
                     const CategoryDecision d = classifier.classify(s);
                     return check ? check(s, d) : d;
                   },
                   held));
  }
  return total;
}
}  // namespace

CategoryEvaluation crossValidateCategories(const std::vector<CategorySample>& always,
                                           const std::vector<CategorySample>& validated, int folds,
                                           const CategoryTrainingOptions& options,
                                           const std::function<void(int, int)>& onFold,
                                           const CategoryCheck& check) {
  if (folds < 2)
    throw InvalidArgument("cross-validation needs at least 2 folds, got " + std::to_string(folds));
  if (validated.size() < static_cast<std::size_t>(folds))
    throw InvalidArgument("cross-validation: " + std::to_string(validated.size()) +
                          " objects to validate for " + std::to_string(folds) + " folds");
  std::vector<std::string> ids;
  std::set<std::string> seen;
  for (const auto& s : validated) {
    if (!seen.insert(s.id).second)
      throw InvalidArgument("cross-validation: object id \"" + s.id + "\" appears twice");
    ids.push_back(s.id);
  }
  return crossValidate(always, validated, assignFolds(ids, folds), folds, options, onFold, check);
}

CategoryEvaluation crossValidateCategoriesBySource(const std::vector<CategorySample>& always,
                                                   const std::vector<CategorySample>& validated,
                                                   const CategoryTrainingOptions& options,
                                                   const std::function<void(int, int)>& onFold,
                                                   const CategoryCheck& check) {
  std::map<std::string, int> sourceFold;
  for (const auto& s : validated) sourceFold.emplace(s.source, 0);
  if (sourceFold.size() < 2)
    throw InvalidArgument("leave-one-source-out needs objects of at least 2 sources, got " +
                          std::to_string(sourceFold.size()));
  int k = 0;
  for (auto& [source, fold] : sourceFold) fold = k++;
  std::map<std::string, int> fold;
  for (const auto& s : validated) {
    if (!fold.emplace(s.id, sourceFold.at(s.source)).second)
      throw InvalidArgument("cross-validation: object id \"" + s.id + "\" appears twice");
  }
  return crossValidate(always, validated, fold, static_cast<int>(sourceFold.size()), options, onFold, check);
}

}  // namespace sagrid
