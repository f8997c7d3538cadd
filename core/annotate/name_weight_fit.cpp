#include "core/annotate/name_weight_fit.h"

#include <algorithm>
#include <map>
#include <set>

namespace sagrid {

nlohmann::json NameWeightFit::toJson() const {
  return {{"weight", weight},
          {"held_out_objects", objects},
          {"sources", sources},
          {"log_likelihood",
           {{"bayes_rule", bayesRuleLogLikelihood}, {"fitted", fittedLogLikelihood}}}};
}

NameWeightFit fitNameWeightBySource(const std::vector<CategorySample>& samples,
                                    const CategoryTrainingOptions& options,
                                    const std::vector<std::string>& classes) {
  std::map<std::string, std::vector<const CategorySample*>> named;
  for (const auto& s : samples)
    if (s.publishedName && !s.source.empty()) named[s.source].push_back(&s);
  NameWeightFit fit;
  fit.sources = named.size();
  if (named.size() < 2) return fit;
  CategoryTrainingOptions shapeOnly = options;
  shapeOnly.inputs.fileName = false;
  std::vector<HeldOutNameCase> cases;
  for (const auto& [source, held] : named) {
    std::vector<CategorySample> rest;
    std::vector<std::pair<std::vector<std::string>, std::string>> otherNames;
    std::set<std::string> restClasses;
    for (const auto& s : samples) {
      if (s.source == source) continue;
      rest.push_back(s);
      restClasses.insert(categoryClass(s.category));
      if (s.publishedName) otherNames.emplace_back(s.nameWords, categoryClass(s.category));
    }
    if (restClasses.size() < 2) continue;  // the other sources cannot train a classifier
    const CategoryClassifier shape = CategoryClassifier::train(rest, shapeOnly);
    const NameEvidence names = NameEvidence::count(otherNames, classes);
    for (const CategorySample* s : held) {
      // An object of a class only its own source holds cannot be decided without it.
      const auto truth = std::find(classes.begin(), classes.end(), categoryClass(s->category));
      if (truth == classes.end() || !restClasses.count(*truth)) continue;
      HeldOutNameCase c;
      c.truth = static_cast<std::size_t>(truth - classes.begin());
      c.logLikelihoods = names.logLikelihoods(s->nameWords);
      const auto p = shape.probabilities(s->descriptor);
      for (const auto& cls : classes) {  // the held-out source may have taken a class with it
        const auto at = std::find(shape.classes().begin(), shape.classes().end(), cls);
        c.shape.push_back(at == shape.classes().end() ? 0.0 : p[at - shape.classes().begin()]);
      }
      cases.push_back(std::move(c));
    }
  }
  fit.objects = cases.size();
  fit.weight = fitNameWeight(cases);
  fit.bayesRuleLogLikelihood = heldOutLogLikelihood(cases, 1.0);
  fit.fittedLogLikelihood = heldOutLogLikelihood(cases, fit.weight);
  return fit;
}

}  // namespace sagrid
