// The weight of the file-name evidence beside the shape (name_evidence.h), learned as the rest of
// the category classifier is: each curated object whose publisher's name the classifier reads is
// decided by a classifier trained without its source (its shape's probabilities; the names counted
// from the other sources' objects), and the weight is the one under which those held-out decisions
// were likeliest (fitNameWeight). The Bayes rule's weight 1 treats the shape and the words as
// independent evidence; trees fitted mostly on generated objects are surer of a real object's
// shape than their record out of source supports, and the words' weight says by how much.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/annotate/category_classifier.h"
#include "core/annotate/name_evidence.h"

namespace sagrid {

struct NameWeightFit {
  double weight = 1.0;
  std::size_t objects = 0, sources = 0;  // the held-out cases and their sources
  // The cases' summed log-probability of their true class under the Bayes rule and under weight.
  double bayesRuleLogLikelihood = 0, fittedLogLikelihood = 0;
  nlohmann::json toJson() const;
};

// The fit over `samples` (those with publishedName and a source; `classes` the classifier's class
// order), each source's shape classifier trained with `options` on every sample of the other
// sources (options.inputs.fileName off; a source whose leaving out leaves one class is skipped,
// and so is an object of a class only its own source holds).
// Where the published names come from fewer than two sources there is nothing to hold out:
// weight 1, sources as counted, no objects.
NameWeightFit fitNameWeightBySource(const std::vector<CategorySample>& samples,
                                    const CategoryTrainingOptions& options,
                                    const std::vector<std::string>& classes);

}  // namespace sagrid
