#include "core/eval/point_scorer_training.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/common/report_cell.h"
#include "core/eval/choice_grid.h"
#include "core/eval/metrics.h"
#include "core/model/model_card.h"
#include "core/points/point_count.h"

namespace sagrid {

std::string categoryOfModel(const std::string& model) { return model::splitModelName(model).first; }

namespace {

using Chooser = std::function<std::vector<Eigen::Vector3f>(const CandidateSet&)>;

// The held-out decisions scorer_cv.md lists (most edits first); the JSON has every one.
constexpr std::size_t kCostliestDecisions = 12;

// Draw d of a fold's learning curve is seeded seed + fold + d * this (no two folds' draws share a
// seed).
constexpr unsigned kDrawSeedStride = 7919;

float objectWeight(const CandidateSet& set, const ScorerTrainingOptions& options) {
  return set.generated ? 1.0f : options.realWeight;
}

std::vector<Eigen::Vector3f> surfaceOf(const CandidateSet& set,
                                       const std::vector<std::size_t>& chosen) {
  std::vector<Eigen::Vector3f> out;
  for (std::size_t i : chosen) out.push_back(set.candidateSurface[i]);
  return out;
}

std::vector<Eigen::Vector3f> chosenSurface(const CandidateSet& set,
                                           const std::vector<float>& probability,
                                           const PointChoice& choice) {
  return surfaceOf(set, chooseCandidates(probability, set.candidates, choice));
}

// Whether two models are of one category (stove.heatsource and stove.togglebutton).
bool sameCategory(const std::string& a, const std::string& b) {
  return a != b && categoryOfModel(a) == categoryOfModel(b);
}

// The sets of each object (source/object): a decision's count reads the object's other models.
using SetsByObject = std::map<std::string, std::vector<const CandidateSet*>>;
SetsByObject setsByObject(const std::vector<const CandidateSet*>& sets) {
  SetsByObject out;
  for (const CandidateSet* set : sets) out[set->source + "/" + set->object].push_back(set);
  return out;
}

// The candidates `scorer` chooses for `set`, its count reading the object's other models of the
// category among `objects`; nullopt where it has no decision for the set's model or the set has no
// candidates (the count's points stand).
std::optional<std::vector<std::size_t>> scorerChoice(const PointScorer& scorer,
                                                     const CandidateSet& set,
                                                     const SetsByObject& objects) {
  const ModelPointScorer* s = scorer.forModel(set.model);
  if (!s || set.candidates.empty()) return std::nullopt;
  std::vector<std::vector<float>> otherModels;
  if (const auto found = objects.find(set.source + "/" + set.object); found != objects.end())
    for (const CandidateSet* other : found->second)
      if (const ModelPointScorer* o = scorer.forModel(other->model);
          o && sameCategory(set.model, other->model))
        otherModels.push_back(countDescription(*o, other->candidates));
  return chosenCandidates(*s, set.candidates, otherModels);
}

// The points of a choice, the count's where there is none.
std::vector<Eigen::Vector3f> pointsOf(const CandidateSet& set,
                                      const std::optional<std::vector<std::size_t>>& chosen) {
  return chosen ? surfaceOf(set, *chosen) : set.keptSurface;
}

// The scorer's points where it decides, else the count's; `sets` holds the objects' other models.
Chooser scorerChooser(const PointScorer& scorer, const std::vector<const CandidateSet*>& sets) {
  return [&scorer, objects = setsByObject(sets)](const CandidateSet& set) {
    return pointsOf(set, scorerChoice(scorer, set, objects));
  };
}

// Per set of `sets`, `scorer`'s ranking cut at the set's true number of points
// (ScorerSourceFold::trueCount; the count's points where it has no decision), found once: the
// fold's figures and its held-out decisions both read it.
using PointsBySet = std::map<const CandidateSet*, std::vector<Eigen::Vector3f>>;
PointsBySet trueCountPoints(const std::vector<const CandidateSet*>& sets,
                            const PointScorer& scorer) {
  PointsBySet points;
  for (const CandidateSet* set : sets) {
    const ModelPointScorer* s = scorer.forModel(set->model);
    if (!s || set->candidates.empty()) {
      points[set] = set->keptSurface;
      continue;
    }
    const PointChoice ranking{0.0f, 0.0f, s->choice.nmsRadius, PointChoice{}.copyThreshold};
    auto order = chooseCandidates(candidateProbabilities(s->classifier, set->candidates),
                                  set->candidates, ranking);
    order.resize(std::min(order.size(), set->truth.size()));
    points[set] = surfaceOf(*set, order);
  }
  return points;
}

// What `scorer` chooses for each of `sets` (scorerChoice), found once: a fold's reports read it
// three times, and a choice runs both looks' trees over every candidate.
using Choices = std::map<const CandidateSet*, std::optional<std::vector<std::size_t>>>;
Choices choicesOf(const std::vector<const CandidateSet*>& sets, const PointScorer& scorer) {
  Choices choices;
  const SetsByObject objects = setsByObject(sets);
  for (const CandidateSet* set : sets) choices[set] = scorerChoice(scorer, *set, objects);
  return choices;
}

std::vector<Eigen::Vector3f> chosenPoints(const Choices& choices, const CandidateSet& set) {
  return pointsOf(set, choices.at(&set));
}

PointEdits editsOf(const CandidateSet& set, const std::vector<Eigen::Vector3f>& chosen) {
  return pointEdits(matchPoints(chosen, set.truth, set.metersPerUnit));
}

// Per object of `sets`: the largest predicted distance among the points chosen (the
// count's points where it has no decision), as annotate's object confidence reads it, whether the
// object needs no edit, and its source.
void addObjectOutcomes(const std::vector<const CandidateSet*>& sets, const Choices& choices,
                       ScorerCrossValidation& cv) {
  std::map<std::string, std::pair<double, PointEdits>> byObject;
  for (const CandidateSet* set : sets) {
    const auto& chosen = choices.at(set);
    auto& [worst, edits] = byObject[set->source + "/" + set->object];
    for (std::size_t i = 0; i < set->candidates.size(); ++i)
      if (chosen ? std::count(chosen->begin(), chosen->end(), i) > 0 : set->candidates[i].kept)
        worst = std::max(worst, static_cast<double>(set->candidates[i].distance));
    edits += editsOf(*set, chosenPoints(choices, *set));
  }
  for (const auto& [object, outcome] : byObject) {
    cv.leastSure.push_back(outcome.first);
    cv.oneKey.push_back(outcome.second.total() == 0);
    cv.objectSources.push_back(object.substr(0, object.rfind('/')));
  }
}

// Per (object, model) of `sets`: what was chosen (the count's points where the scorer has no
// decision), its edits and errors, and the edits with the true number of points (`trueCount`).
void addHeldOutDecisions(const std::vector<const CandidateSet*>& sets, const Choices& choices,
                         const PointsBySet& trueCount, ScorerCrossValidation& cv) {
  for (const CandidateSet* set : sets) {
    HeldOutDecision d{set->source, set->object, set->model, set->truth.size()};
    const auto chosen = chosenPoints(choices, *set);
    d.chosenPoints = chosen.size();
    d.edits = editsOf(*set, chosen);
    d.trueCountEdits = editsOf(*set, trueCount.at(set));
    if (!set->truth.empty()) {
      if (!chosen.empty())
        d.bestPointError = nearestDistance(chosen.front(), set->truth, set->metersPerUnit);
      for (const auto& c : set->candidateSurface)
        d.nearestCandidateError =
            std::fmin(d.nearestCandidateError, nearestDistance(c, set->truth, set->metersPerUnit));
    }
    for (const auto& t : set->truth)
      d.truthReached +=
          std::any_of(set->candidateSurface.begin(), set->candidateSurface.end(),
                      [&](const Eigen::Vector3f& c) {
                        return (c - t).norm() * set->metersPerUnit <= kMatchRadiusMeters;
                      });
    cv.decisions.push_back(std::move(d));
  }
}

ConfidenceCheck checkConfidence(const std::string& map, const ConfidenceCalibration& c,
                                const std::vector<double>& leastSure,
                                const std::vector<bool>& oneKey) {
  ConfidenceCheck check{map};
  for (std::size_t i = 0; i < leastSure.size(); ++i) {
    const double p = std::clamp(c.probability(leastSure[i]), 1e-9, 1 - 1e-9);
    check.logLoss -= oneKey[i] ? std::log(p) : std::log(1 - p);
    check.brier += (p - oneKey[i]) * (p - oneKey[i]);
    check.meanProbability += p;
  }
  const double n = static_cast<double>(std::max<std::size_t>(leastSure.size(), 1));
  check.logLoss /= n;
  check.brier /= n;
  check.meanProbability /= n;
  return check;
}

PointChoiceFigures figuresOf(const std::vector<const CandidateSet*>& sets, const Chooser& choose) {
  PointChoiceFigures f;
  std::map<std::string, PointEdits> byObject;
  double errorSum = 0;
  for (const CandidateSet* set : sets) {
    const auto chosen = choose(*set);
    const PointEdits e = editsOf(*set, chosen);
    byObject[set->source + "/" + set->object] += e;
    f.edits += e;
    if (!set->truth.empty() && !chosen.empty()) {
      errorSum += nearestDistance(chosen.front(), set->truth, set->metersPerUnit);
      ++f.singleErrors;
    }
  }
  CuratorEffortAccumulator effort;
  for (const auto& [object, e] : byObject) effort.addObject(e);
  f.effort = effort.result();
  f.singleError = f.singleErrors ? errorSum / static_cast<double>(f.singleErrors) : NAN;
  return f;
}

// Each object's edits (its sets summed), by source/object.
std::map<std::string, double> editsByObject(const std::vector<const CandidateSet*>& sets,
                                            const Chooser& choose) {
  std::map<std::string, double> edits;
  for (const CandidateSet* set : sets)
    edits[set->source + "/" + set->object] +=
        static_cast<double>(editsOf(*set, choose(*set)).total());
  return edits;
}

// Figures pooled over several arms on objects (folds' objects, or draws on the same objects):
// edits and errors summed, per-object figures averaged by object count.
PointChoiceFigures pooled(const std::vector<const PointChoiceFigures*>& parts) {
  PointChoiceFigures t;
  double errorSum = 0;
  for (const PointChoiceFigures* f : parts) {
    t.edits += f->edits;
    if (f->singleErrors) errorSum += f->singleError * static_cast<double>(f->singleErrors);
    t.singleErrors += f->singleErrors;
    t.effort.objects += f->effort.objects;
    t.effort.editsPerObject += f->effort.editsPerObject * f->effort.objects;
    t.effort.handPointsPerObject += f->effort.handPointsPerObject * f->effort.objects;
    t.effort.oneKeyShare += f->effort.oneKeyShare * f->effort.objects;
  }
  const double n = std::max<std::size_t>(t.effort.objects, 1);
  t.effort.editsPerObject /= n;
  t.effort.handPointsPerObject /= n;
  t.effort.oneKeyShare /= n;
  t.singleError = t.singleErrors ? errorSum / static_cast<double>(t.singleErrors) : NAN;
  return t;
}

// The boosting options with the field's features monotone: a candidate never scores higher only
// for a worse field (its distance, above the object's best, its rank), nor, in the second look,
// for a less probable first look. Leave one source out: 30 -> 32 % one key, best point 6.8 -> 6.4
// cm, 0.585 -> 0.589 edits per hand point (resources/models/README.md).
BoostingOptions fieldMonotone(BoostingOptions boosting, bool context) {
  const std::size_t d = candidateFeatureNames().size();
  boosting.monotone.assign(d + (context ? kContextFeatureCount : 0), 0);
  for (const char* name : {"distance", "distance_above_best", "distance_rank"})
    boosting.monotone[candidateFeatureIndex(name)] = -1;
  if (context) {
    boosting.monotone[d + 0] = +1;  // first_look
    boosting.monotone[d + 1] = +1;  // against_best
    boosting.monotone[d + 2] = -1;  // rank
  }
  return boosting;
}

// A set's candidates' features, one row each.
std::vector<std::vector<float>> featureRows(const CandidateSet& set) {
  std::vector<std::vector<float>> rows;
  for (const auto& c : set.candidates) rows.push_back(c.features);
  return rows;
}

// The training rows of `sets`' candidates (their features, or what `rowsOf` makes of a set), with
// labels and weights.
struct TrainingRows {
  std::vector<std::vector<float>> rows;
  std::vector<bool> positive;
  std::vector<float> weight;
};
TrainingRows trainingRows(
    const std::vector<const CandidateSet*>& sets, const ScorerTrainingOptions& options,
    const std::function<std::vector<std::vector<float>>(std::size_t)>& rowsOf) {
  TrainingRows t;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const auto labels = candidateLabels(*sets[i], kMatchRadiusMeters);
    auto rows = rowsOf(i);
    for (std::size_t c = 0; c < rows.size(); ++c) {
      t.rows.push_back(std::move(rows[c]));
      t.positive.push_back(labels[c]);
      t.weight.push_back(objectWeight(*sets[i], options));
    }
  }
  return t;
}

// The second look's trees (CandidateClassifier::contextTrees): trained on context features under
// first-look probabilities of trees that did not see the object (kContextFolds folds of the
// objects, dealt in name order), so the second look learns how far a first look on unseen objects
// is to be trusted.
constexpr std::size_t kContextFolds = 4;
BoostedTrees fitContextTrees(const std::vector<const CandidateSet*>& sets,
                             const ScorerTrainingOptions& options,
                             std::vector<std::vector<float>>& firstLook) {
  std::set<std::string> names;
  for (const CandidateSet* set : sets) names.insert(set->source + "/" + set->object);
  const std::vector<std::string> objects(names.begin(), names.end());
  std::vector<std::size_t> fold(sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i)
    fold[i] = static_cast<std::size_t>(std::lower_bound(objects.begin(), objects.end(),
                                                        sets[i]->source + "/" + sets[i]->object) -
                                       objects.begin()) %
              kContextFolds;
  firstLook.assign(sets.size(), {});
  for (std::size_t f = 0; f < kContextFolds; ++f) {
    std::vector<const CandidateSet*> others;
    for (std::size_t i = 0; i < sets.size(); ++i)
      if (fold[i] != f) others.push_back(sets[i]);
    if (others.size() == sets.size()) continue;  // no object of its own (fewer than 4)
    const auto t =
        trainingRows(others, options, [&](std::size_t i) { return featureRows(*others[i]); });
    // A fold whose other objects give one class no weight (a few curated objects, or a real
    // weight of 0) gives no first look: its objects' context reads probabilities of 0.
    double positive = 0, negative = 0;
    for (std::size_t r = 0; r < t.rows.size(); ++r)
      (t.positive[r] ? positive : negative) += t.weight[r];
    if (!(positive > 0) || !(negative > 0)) continue;
    CandidateClassifier look;
    look.trees =
        fitBoostedTrees(t.rows, t.positive, t.weight, fieldMonotone(options.boosting, false));
    for (std::size_t i = 0; i < sets.size(); ++i)
      if (fold[i] == f) firstLook[i] = candidateProbabilities(look, sets[i]->candidates);
  }
  const auto t = trainingRows(sets, options, [&](std::size_t i) {
    if (firstLook[i].size() != sets[i]->candidates.size())
      firstLook[i].assign(sets[i]->candidates.size(), 0.0f);
    return withContext(sets[i]->candidates, firstLook[i]);
  });
  return fitBoostedTrees(t.rows, t.positive, t.weight, fieldMonotone(options.boosting, true));
}

// The learned count's trees (core/points/point_count.h) over `sets`' first looks by trees that
// did not see them, with `otherModels` (per set, the count descriptions of its object's other
// models of the category); nullopt where the sets give one answer alone (every object k points or
// more).
std::optional<BoostedTrees> fitCountTrees(
    const std::vector<const CandidateSet*>& sets, const std::vector<std::vector<float>>& firstLook,
    float nmsRadius, const std::vector<std::vector<std::vector<float>>>& otherModels,
    const ScorerTrainingOptions& options) {
  TrainingRows t;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (sets[i]->candidates.empty()) continue;
    const auto rows = countRows(withOtherModels(
        countFeatures(sets[i]->candidates, firstLook[i], nmsRadius), otherModels[i]));
    for (std::size_t k = 0; k < rows.size(); ++k) {
      t.rows.push_back(rows[k]);
      t.positive.push_back(sets[i]->truth.size() > k);
      t.weight.push_back(objectWeight(*sets[i], options));
    }
  }
  if (std::count(t.positive.begin(), t.positive.end(), true) == 0 ||
      std::count(t.positive.begin(), t.positive.end(), false) == 0)
    return std::nullopt;
  BoostingOptions boosting = options.boosting;
  boosting.monotone.assign(countFeatureNames().size(), 0);
  boosting.monotone.back() = -1;  // never more likely to have k points or more for a larger k
  return fitBoostedTrees(t.rows, t.positive, t.weight, boosting);
}

// One model's decision before its learned count, and its sets' first looks by trees that did
// not see them (empty without the second look): the count learns on them.
struct FittedDecision {
  ModelPointScorer decision;
  std::vector<std::vector<float>> unseenFirstLook;
};

FittedDecision fitModel(const std::vector<const CandidateSet*>& sets,
                        const ScorerTrainingOptions& options) {
  const auto t = trainingRows(sets, options, [&](std::size_t i) { return featureRows(*sets[i]); });
  FittedDecision fitted;
  ModelPointScorer& best = fitted.decision;
  std::vector<std::vector<float>>& unseenFirstLook = fitted.unseenFirstLook;
  if (options.trees) {
    best.classifier.trees =
        fitBoostedTrees(t.rows, t.positive, t.weight, fieldMonotone(options.boosting, false));
    if (options.context)
      best.classifier.contextTrees = fitContextTrees(sets, options, unseenFirstLook);
  } else {
    best.classifier = fitCandidateClassifier(t.rows, t.positive, t.weight, options.ridge);
  }
  // The choice is fitted on the training objects' own probabilities. (With two looks, fitting it
  // under first looks that did not see the object instead was tried: 0.613 edits per hand point
  // leave one source out against 0.585; resources/models/README.md.)
  std::vector<std::vector<float>> probabilities;
  for (const CandidateSet* set : sets)
    probabilities.push_back(candidateProbabilities(best.classifier, set->candidates));
  // Every choice's weighted edits on the training objects; copy threshold and radius outside.
  const std::size_t radii = options.nmsRadii.size();
  ChoiceGrid grid(options.copyThresholds.size() * radii, options.keepThresholds.size(),
                  options.addThresholds.size());
  const auto choiceAt = [&](std::size_t outer, std::size_t keep, std::size_t add) {
    return PointChoice{options.keepThresholds[keep], options.addThresholds[add],
                       options.nmsRadii[outer % radii], options.copyThresholds[outer / radii]};
  };
  for (std::size_t outer = 0; outer < options.copyThresholds.size() * radii; ++outer)
    for (std::size_t keep = 0; keep < options.keepThresholds.size(); ++keep)
      for (std::size_t add = 0; add < options.addThresholds.size(); ++add) {
        const PointChoice choice = choiceAt(outer, keep, add);
        for (std::size_t i = 0; i < sets.size(); ++i)
          if (!sets[i]->candidates.empty())
            grid.cost(outer, keep, add) +=
                objectWeight(*sets[i], options) *
                editsOf(*sets[i], chosenSurface(*sets[i], probabilities[i], choice)).total();
      }
  const ChoiceGrid::Index taken = grid.best(options.smoothChoice);
  best.choice = choiceAt(taken.outer, taken.keep, taken.add);
  return fitted;
}

// The learned counts of `fitted`'s models, each over its sets and the count descriptions of
// their objects' other models of the category (ScorerTrainingOptions::otherModelsCount), all
// under first looks of trees that did not see the object.
void fitCounts(const std::map<std::string, std::vector<const CandidateSet*>>& byModel,
               std::map<std::string, FittedDecision>& fitted,
               const ScorerTrainingOptions& options) {
  // Per model, each object's count description under the unseen first look.
  std::map<std::string, std::map<std::string, std::vector<float>>> described;
  for (const auto& [model, f] : fitted) {
    if (f.unseenFirstLook.empty()) continue;
    const auto& sets = byModel.at(model);
    for (std::size_t i = 0; i < sets.size(); ++i)
      if (!sets[i]->candidates.empty())
        described[model][sets[i]->source + "/" + sets[i]->object] =
            countFeatures(sets[i]->candidates, f.unseenFirstLook[i], f.decision.choice.nmsRadius);
  }
  for (auto& [model, f] : fitted) {
    if (f.unseenFirstLook.empty()) continue;
    const auto& sets = byModel.at(model);
    std::vector<std::vector<std::vector<float>>> others(sets.size());
    for (std::size_t i = 0; i < sets.size() && options.otherModelsCount; ++i)
      for (const auto& [other, objects] : described) {
        const auto found = objects.find(sets[i]->source + "/" + sets[i]->object);
        if (sameCategory(model, other) && found != objects.end())
          others[i].push_back(found->second);
      }
    f.decision.countTrees =
        fitCountTrees(sets, f.unseenFirstLook, f.decision.choice.nmsRadius, others, options);
  }
}

}  // namespace

PointScorer trainPointScorer(const std::vector<const CandidateSet*>& sets,
                             const ScorerTrainingOptions& options) {
  std::map<std::string, std::vector<const CandidateSet*>> byModel;
  for (const CandidateSet* set : sets) {
    if (options.skipUnreached && !set->truth.empty()) {
      const auto labels = candidateLabels(*set, kMatchRadiusMeters);
      if (std::none_of(labels.begin(), labels.end(), [](bool point) { return point; })) continue;
    }
    byModel[set->model].push_back(set);
  }
  PointScorer scorer;
  if (!sets.empty()) scorer.passesOff = sets.front()->passesOff;
  for (const CandidateSet* set : sets)
    if (set->passesOff != scorer.passesOff)
      throw InvalidArgument("point scorer: candidates made with different passes (" + set->object +
                            " of " + set->source + " differs from " + sets.front()->object +
                            "): make them all with the same eval flags");
  std::map<std::string, FittedDecision> fitted;
  for (const auto& [model, modelSets] : byModel) {
    bool hasPoint = false, hasOther = false;
    for (const CandidateSet* set : modelSets)
      for (bool label : candidateLabels(*set, kMatchRadiusMeters))
        (label ? hasPoint : hasOther) = true;
    if (!hasPoint || !hasOther) continue;
    for (const CandidateSet* set : modelSets)
      if (set->networkWeights != modelSets.front()->networkWeights)
        throw InvalidArgument("point scorer: the candidates of " + model + " were made by " +
                              "different weights (" + set->object + " of " + set->source +
                              " differs from " + modelSets.front()->object +
                              "): make them all with one models folder");
    fitted[model] = fitModel(modelSets, options);
    fitted[model].decision.networkWeights = modelSets.front()->networkWeights;
  }
  if (options.learnedCount) fitCounts(byModel, fitted, options);
  for (auto& [model, f] : fitted) scorer.byModel[model] = std::move(f.decision);
  if (scorer.byModel.empty())
    throw InvalidArgument("point scorer: no model has candidates that are points and others");
  std::set<std::string> sources;
  std::size_t generated = 0;
  for (const CandidateSet* set : sets)
    if (set->generated)
      ++generated;
    else
      sources.insert(set->source);
  std::ostringstream on;
  on << sets.size() << " candidate sets (" << generated << " generated) from " << sources.size()
     << " real sources";
  scorer.trainedOn = on.str();
  return scorer;
}

ScorerCrossValidation crossValidatePointScorer(const std::vector<CandidateSet>& sets,
                                               const ScorerTrainingOptions& options,
                                               const ScorerCurveOptions& curveOptions) {
  std::vector<const CandidateSet*> generated;
  std::map<std::string, std::vector<const CandidateSet*>> realBySource;
  std::set<std::string> generatedObjects, realObjects;
  for (const auto& set : sets) {
    if (set.generated) {
      generated.push_back(&set);
      generatedObjects.insert(set.source + "/" + set.object);
    } else {
      realBySource[set.source].push_back(&set);
      realObjects.insert(set.source + "/" + set.object);
    }
  }
  if (realBySource.size() < 2)
    throw InvalidArgument(
        "point scorer cross-validation needs curated real objects of two "
        "sources or more, got " +
        std::to_string(realBySource.size()));
  ScorerCrossValidation cv;
  cv.tunedOn = curveOptions.tunedOn;
  cv.ks = curveOptions.ks;
  cv.draws = std::max(curveOptions.draws, 1u);
  cv.generatedObjects = generatedObjects.size();
  cv.realObjects = realObjects.size();
  std::optional<PointScorer> generatedOnly;
  if (!generated.empty()) generatedOnly = trainPointScorer(generated, options);
  const Chooser count = [](const CandidateSet& set) { return set.keptSurface; };
  unsigned foldIndex = 0;
  for (const auto& [source, held] : realBySource) {
    std::vector<const CandidateSet*> training = generated;
    std::map<std::string, std::vector<const CandidateSet*>> otherObjects;
    for (const auto& [other, otherSets] : realBySource)
      if (other != source) {
        training.insert(training.end(), otherSets.begin(), otherSets.end());
        for (const CandidateSet* set : otherSets)
          otherObjects[other + "/" + set->object].push_back(set);
      }
    const PointScorer withCurated = trainPointScorer(training, options);
    ScorerSourceFold fold;
    fold.source = source;
    fold.count = figuresOf(held, count);
    fold.generatedOnly =
        generatedOnly ? figuresOf(held, scorerChooser(*generatedOnly, held)) : fold.count;
    const Choices choices = choicesOf(held, withCurated);
    fold.withCurated =
        figuresOf(held, [&](const CandidateSet& set) { return chosenPoints(choices, set); });
    const PointsBySet trueCount = trueCountPoints(held, withCurated);
    fold.trueCount =
        figuresOf(held, [&](const CandidateSet& set) { return trueCount.at(&set); });
    addObjectOutcomes(held, choices, cv);
    addHeldOutDecisions(held, choices, trueCount, cv);
    fold.objects = fold.count.effort.objects;
    // The learning curve: k objects of the other sources, drawn `draws` times per fold (the
    // figures pooled over the draws).
    std::vector<std::string> objects;
    for (const auto& [object, objectSets] : otherObjects) objects.push_back(object);
    std::vector<std::vector<std::string>> orders;
    for (unsigned d = 0; d < cv.draws; ++d) {
      std::mt19937 rng(curveOptions.seed + foldIndex + kDrawSeedStride * d);
      orders.push_back(objects);
      std::shuffle(orders.back().begin(), orders.back().end(), rng);
    }
    ++foldIndex;
    for (std::size_t k : curveOptions.ks) {
      std::vector<PointChoiceFigures> draws;
      for (const auto& order : orders) {
        std::vector<const CandidateSet*> some = generated;
        for (std::size_t i = 0; i < std::min(k, order.size()); ++i)
          some.insert(some.end(), otherObjects[order[i]].begin(), otherObjects[order[i]].end());
        try {
          draws.push_back(figuresOf(held, scorerChooser(trainPointScorer(some, options), held)));
        } catch (const InvalidArgument&) {
          draws.push_back(fold.count);  // nothing to fit on: the count stands
        }
      }
      std::vector<const PointChoiceFigures*> parts;
      for (const auto& f : draws) parts.push_back(&f);
      fold.curve.push_back(pooled(parts));
    }
    cv.folds.push_back(fold);
  }
  // Totals over every held-out object: each fold's decision on its own objects.
  using Arm = std::function<const PointChoiceFigures&(const ScorerSourceFold&)>;
  auto total = [&](const Arm& arm, bool unseenOnly) {
    std::vector<const PointChoiceFigures*> parts;
    for (const auto& fold : cv.folds)
      if (!unseenOnly || !std::count(cv.tunedOn.begin(), cv.tunedOn.end(), fold.source))
        parts.push_back(&arm(fold));
    return pooled(parts);
  };
  for (bool unseen : {false, true}) {
    (unseen ? cv.unseenCount : cv.count) = total(
        [](const auto& f) -> const auto& { return f.count; }, unseen);
    (unseen ? cv.unseenGeneratedOnly : cv.generatedOnly) = total(
        [](const auto& f) -> const auto& { return f.generatedOnly; }, unseen);
    (unseen ? cv.unseenWithCurated : cv.withCurated) = total(
        [](const auto& f) -> const auto& { return f.withCurated; }, unseen);
    (unseen ? cv.unseenTrueCount : cv.trueCount) = total(
        [](const auto& f) -> const auto& { return f.trueCount; }, unseen);
    for (std::size_t k = 0; k < cv.ks.size(); ++k)
      (unseen ? cv.unseenCurve : cv.curve)
          .push_back(total(
              [k](const auto& f) -> const auto& { return f.curve[k]; }, unseen));
  }
  std::size_t truthPoints = 0, reached = 0;
  for (const HeldOutDecision& d : cv.decisions)
    truthPoints += d.truthPoints, reached += d.truthReached;
  cv.candidateRecall = truthPoints ? static_cast<double>(reached) / truthPoints : NAN;
  if (!cv.leastSure.empty()) {
    cv.confidence = fitConfidence(cv.leastSure, cv.oneKey);
    cv.confidence->fittedOn =
        "the curated objects' points decided leave one source out (sagrid scorer cv)";
    for (const CandidateSet& set : sets)
      if (!set.networkWeights.empty())
        cv.confidence->networkWeights.emplace(set.model, set.networkWeights);
  }
  // The confidence fitted on the tuned-on sources alone, and the other one given, on the rest.
  std::vector<double> tunedSure, unseenSure;
  std::vector<bool> tunedRight, unseenRight;
  for (std::size_t i = 0; i < cv.leastSure.size(); ++i) {
    const bool tuned = std::count(cv.tunedOn.begin(), cv.tunedOn.end(), cv.objectSources[i]) > 0;
    (tuned ? tunedSure : unseenSure).push_back(cv.leastSure[i]);
    (tuned ? tunedRight : unseenRight).push_back(cv.oneKey[i]);
  }
  if (!tunedSure.empty() && !unseenSure.empty()) {
    cv.unseenObjects = unseenSure.size();
    cv.unseenOneKeyShare =
        static_cast<double>(std::count(unseenRight.begin(), unseenRight.end(), true)) /
        static_cast<double>(unseenRight.size());
    cv.unseenConfidence.push_back(checkConfidence("fitted on the tuned-on sources' objects",
                                                  fitConfidence(tunedSure, tunedRight), unseenSure,
                                                  unseenRight));
    if (curveOptions.otherConfidence)
      cv.unseenConfidence.push_back(checkConfidence(curveOptions.otherConfidenceName,
                                                    *curveOptions.otherConfidence, unseenSure,
                                                    unseenRight));
  }
  return cv;
}

namespace {
// A category's models whose mixes the guard judges (2^n mixes; a stove and a sink have two).
constexpr std::size_t kMostGuardedModelsPerCategory = 8;

// `base` with `fresh`'s decisions for `models` (none where `fresh` has none: the count's points).
PointScorer withDecisionsOf(PointScorer base, const PointScorer& fresh,
                            const std::vector<std::string>& models) {
  for (const auto& model : models)
    if (const ModelPointScorer* decision = fresh.forModel(model))
      base.byModel[model] = *decision;
    else
      base.byModel.erase(model);
  return base;
}
}  // namespace

ScorerGuard guardPointScorer(const PointScorer* current, const PointScorer& fresh,
                             const std::vector<CandidateSet>& heldOut,
                             const std::vector<const CandidateSet*>& training) {
  if (heldOut.empty()) throw InvalidArgument("scorer guard: no held-out candidates");
  std::set<std::string> trained;
  for (const CandidateSet* set : training) trained.insert(set->source + "/" + set->object);
  for (const auto& set : heldOut) {
    if (trained.count(set.source + "/" + set.object))
      throw InvalidArgument("scorer guard: held-out object " + set.object + " of " + set.source +
                            " is also training data");
    if (set.passesOff != fresh.passesOff || (current && current->passesOff != fresh.passesOff))
      throw InvalidArgument("scorer guard: the held-out candidates (" + set.object +
                            "), the new scorer and the current one were made with different "
                            "passes: make them with the same eval flags");
  }
  const PointScorer none;
  const PointScorer& was = current ? *current : none;
  std::map<std::string, std::vector<const CandidateSet*>> byModel;
  std::vector<const CandidateSet*> all;
  for (const auto& set : heldOut) {
    byModel[set.model].push_back(&set);
    all.push_back(&set);
  }
  ScorerGuard guard;
  std::map<std::string, std::vector<std::string>> categories;  // category -> its judged models
  std::map<std::string, std::size_t> verdictOf;                // model -> its verdict's index
  for (const auto& [model, sets] : byModel) {
    ScorerVerdict v;
    v.model = model;
    const auto before = figuresOf(sets, scorerChooser(was, all));
    v.currentEdits = before.edits.total();
    v.newEdits = figuresOf(sets, scorerChooser(fresh, all)).edits.total();
    v.handPoints = before.edits.handPoints;
    guard.currentEdits += v.currentEdits;
    guard.newEdits += v.newEdits;
    categories[categoryOfModel(model)].push_back(model);
    verdictOf[model] = guard.byModel.size();
    guard.byModel.push_back(v);
  }
  // A category's decisions read each other (each model's count reads the category's other
  // models), so every mix of its current and new decisions is judged on the category's held-out
  // objects as a whole and the one with the fewest edits adopted: the mix adopted is the mix
  // judged. Mixes with fewer new decisions come first, so a tie keeps the current ones.
  for (const auto& [category, models] : categories) {
    if (models.size() > kMostGuardedModelsPerCategory)
      throw InvalidArgument("scorer guard: category " + category + " has " +
                            std::to_string(models.size()) + " models; the guard judges every mix "
                            "of at most " + std::to_string(kMostGuardedModelsPerCategory));
    std::vector<const CandidateSet*> sets;
    for (const auto& model : models)
      sets.insert(sets.end(), byModel.at(model).begin(), byModel.at(model).end());
    std::vector<std::size_t> mixes(std::size_t{1} << models.size());
    std::iota(mixes.begin(), mixes.end(), std::size_t{0});
    std::stable_sort(mixes.begin(), mixes.end(), [](std::size_t a, std::size_t b) {
      return std::bitset<kMostGuardedModelsPerCategory>(a).count() <
             std::bitset<kMostGuardedModelsPerCategory>(b).count();
    });
    // Each mix's edits per held-out object of the category; the mix with the fewest in all is
    // adopted only where it beats the current decisions by more than the standard error of the
    // per-object differences (core/common/paired_change.h), else the current ones stay.
    const std::vector<std::string>& categoryModels = models;  // lambdas may not capture bindings (C++17)
    const auto editsOfMix = [&](std::size_t mix) {
      std::vector<std::string> taken;
      for (std::size_t i = 0; i < categoryModels.size(); ++i)
        if ((mix >> i) & 1) taken.push_back(categoryModels[i]);
      return editsByObject(sets, scorerChooser(withDecisionsOf(was, fresh, taken), all));
    };
    const auto total = [](const std::map<std::string, double>& edits) {
      double sum = 0;
      for (const auto& [object, e] : edits) sum += e;
      return static_cast<std::size_t>(std::lround(sum));
    };
    const std::map<std::string, double> current = editsOfMix(0);
    const std::size_t currentEdits = total(current);
    std::size_t best = 0, bestEdits = currentEdits;
    std::map<std::string, double> bestByObject;
    const std::size_t allNew = mixes.size() - 1;
    for (std::size_t mix : mixes) {
      if (mix == 0) continue;
      std::map<std::string, double> edits = editsOfMix(mix);
      if (mix == allNew) {
        guard.categoryEdits[category] = pairById(current, edits);
        if (best == 0) bestByObject = edits;  // judged against, where no mix has fewer edits
      }
      if (total(edits) < bestEdits)
        best = mix, bestEdits = total(edits), bestByObject = std::move(edits);
    }
    const PairedChange change = pairedChange(pairById(current, bestByObject));
    if (best != 0 && !change.clearlyBetter()) best = 0, bestEdits = currentEdits;
    for (std::size_t i = 0; i < models.size(); ++i) {
      ScorerVerdict& v = guard.byModel[verdictOf.at(models[i])];
      v.adopted = (best >> i) & 1;
      v.categoryCurrentEdits = currentEdits;
      v.categoryAdoptedEdits = bestEdits;
      v.categoryJudged = models.size();
      v.categoryNoise = change.noise * static_cast<double>(change.objects);
    }
    guard.adoptedEdits += bestEdits;
    guard.adopted = guard.adopted || best != 0;
  }
  for (const auto& [model, decision] : fresh.byModel)
    if (!byModel.count(model)) guard.byModel.push_back({model, 0, 0, 0, false});
  return guard;
}

bool ScorerGuard::adoptedWhole() const {
  return std::all_of(byModel.begin(), byModel.end(),
                     [](const ScorerVerdict& v) { return v.adopted; });
}

PointScorer adoptedScorer(const PointScorer* current, const PointScorer& fresh,
                          const ScorerGuard& guard) {
  std::vector<std::string> adopted;
  for (const ScorerVerdict& v : guard.byModel)
    if (v.adopted) adopted.push_back(v.model);
  PointScorer out = withDecisionsOf(current ? *current : PointScorer{}, fresh, adopted);
  out.passesOff = fresh.passesOff;
  out.trainedOn = fresh.trainedOn;
  if (!guard.adoptedWhole()) {
    const std::string models = modelsWhere(guard, true);
    out.trainedOn += "; adopted for " + (models.empty() ? std::string("no model") : models) +
                     ", the other models keep the decision before";
  }
  return out;
}

std::string modelsWhere(const ScorerGuard& guard, bool adopted) {
  std::string models;
  for (const ScorerVerdict& v : guard.byModel)
    if (v.adopted == adopted) models += (models.empty() ? "" : ", ") + v.model;
  return models;
}

std::string toString(const ScorerVerdict& v) {
  std::string line = v.model + ": " + std::to_string(v.currentEdits) + " -> " +
                     std::to_string(v.newEdits) + " edits on " + std::to_string(v.handPoints) +
                     " held-out points: " + (v.adopted ? "adopted" : "the decision before stays");
  const std::string noise = "noise " + reportCell(v.categoryNoise, "%.1f") + " edits";
  if (v.categoryJudged > 1)
    line += " (" + categoryOfModel(v.model) +
            " judged as a whole: " + std::to_string(v.categoryCurrentEdits) + " -> " +
            std::to_string(v.categoryAdoptedEdits) + " edits with the decisions adopted, " + noise +
            ")";
  else
    line += " (" + noise + ")";
  return line;
}

nlohmann::json toJson(const ScorerGuard& guard) {
  nlohmann::json models = nlohmann::json::array();
  for (const auto& v : guard.byModel)
    models.push_back(
        {{"model", v.model},
         {"current_edits", v.currentEdits},
         {"new_edits", v.newEdits},
         {"hand_points", v.handPoints},
         {"category_current_edits", v.categoryCurrentEdits},
         {"category_adopted_edits", v.categoryAdoptedEdits},
         {"category_judged", v.categoryJudged},
         {"category_noise_edits",
          std::isfinite(v.categoryNoise) ? nlohmann::json(v.categoryNoise) : nlohmann::json()},
         {"adopted", v.adopted}});
  return {{"current_edits", guard.currentEdits},   {"new_edits", guard.newEdits},
          {"adopted_edits", guard.adoptedEdits},   {"adopted", guard.adopted},
          {"adopted_whole", guard.adoptedWhole()}, {"models", models}};
}

double PointChoiceFigures::editsPerHandPoint() const {
  return edits.handPoints ? static_cast<double>(edits.total()) / edits.handPoints : NAN;
}

namespace {
std::string cells(const PointChoiceFigures& f) {
  return reportCell(f.editsPerHandPoint(), "%.2f") + " | " +
         reportCell(100 * f.effort.oneKeyShare, "%.0f %%") + " | " +
         reportCell(100 * f.singleError, "%.1f");
}
}  // namespace

nlohmann::json toJson(const PointChoiceFigures& f) {
  return {{"objects", f.effort.objects},           {"edits", f.edits.total()},
          {"hand_points", f.edits.handPoints},     {"edits_per_hand_point", f.editsPerHandPoint()},
          {"one_key_share", f.effort.oneKeyShare}, {"single_error_m", f.singleError}};
}

double signalAuc(const ScorerCrossValidation& cv) {
  double pairs = 0, ordered = 0;
  for (std::size_t a = 0; a < cv.leastSure.size(); ++a)
    for (std::size_t b = 0; b < cv.leastSure.size(); ++b)
      if (cv.oneKey[a] && !cv.oneKey[b]) {
        ++pairs;
        ordered += cv.leastSure[a] < cv.leastSure[b]    ? 1.0
                   : cv.leastSure[a] == cv.leastSure[b] ? 0.5
                                                        : 0.0;
      }
  return pairs > 0 ? ordered / pairs : NAN;
}

std::string scorerCrossValidationMarkdown(const ScorerCrossValidation& cv) {
  std::ostringstream md;
  md << "# Learned point decision, leave one source out\n\n"
     << cv.realObjects << " curated real objects in " << cv.folds.size() << " sources; "
     << cv.generatedObjects << " generated objects always in training. Each source's objects are "
     << "decided by a scorer fitted without them. Edits: per ground-truth point (placing every "
     << "point by hand = 1). Single-point error: the best point's distance to the nearest true "
     << "point, cm. Candidates reach " << reportCell(100 * cv.candidateRecall, "%.0f %%")
     << " of the true points within 5 cm (the most any choice can get right).\n\n"
     << "| source | objects | the count: edits | one key | error | generated only: edits | one key "
        "| error | + curated of other sources: edits | one key | error |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& f : cv.folds)
    md << "| " << f.source << " | " << f.objects << " | " << cells(f.count) << " | "
       << cells(f.generatedOnly) << " | " << cells(f.withCurated) << " |\n";
  md << "| **all** | " << cv.count.effort.objects << " | " << cells(cv.count) << " | "
     << cells(cv.generatedOnly) << " | " << cells(cv.withCurated) << " |\n";
  if (!cv.tunedOn.empty())
    md << "| **sources no pass was made on** | " << cv.unseenCount.effort.objects << " | "
       << cells(cv.unseenCount) << " | " << cells(cv.unseenGeneratedOnly) << " | "
       << cells(cv.unseenWithCurated) << " |\n";
  md << "\n## With the true number of points\n\nEach held-out decision's ranking (the last "
        "column group above) cut at its true number of points, the suppression radius kept, no "
        "threshold or copy: what a perfect count decision would leave to the curator.\n\n"
     << "| objects | edits | one key | error |\n|---|---|---|---|\n"
     << "| **all** | " << cells(cv.trueCount) << " |\n";
  if (!cv.tunedOn.empty())
    md << "| **sources no pass was made on** | " << cells(cv.unseenTrueCount) << " |\n";
  if (!cv.ks.empty()) {
    md << "\n## Learning curve: k curated objects of the other sources in training\n\n"
       << "Generated objects always in training; k objects drawn " << cv.draws
       << " time(s) per fold, figures pooled over the draws (k = 0: generated only).\n\n"
       << "| k | edits | one key | error |"
       << (cv.tunedOn.empty() ? "" : " unseen sources: edits | one key | error |")
       << "\n|---|---|---|---|" << (cv.tunedOn.empty() ? "" : "---|---|---|") << "\n";
    for (std::size_t k = 0; k < cv.ks.size(); ++k) {
      md << "| " << cv.ks[k] << " | " << cells(cv.curve[k]) << " |";
      if (!cv.tunedOn.empty()) md << ' ' << cells(cv.unseenCurve[k]) << " |";
      md << "\n";
    }
  }
  if (!cv.decisions.empty()) {
    // Per model: how far the candidates reach and how the first point fares against the best
    // candidate (the ranking's share of the error).
    struct ModelTotals {
      std::size_t decisions = 0, truth = 0, reached = 0, farFirst = 0, farFirstReachable = 0;
      std::size_t chosen = 0, unreachableAdditions = 0;
      PointEdits edits, trueCountEdits;
      double first = 0, nearest = 0;
    };
    std::map<std::string, ModelTotals> byModel;
    for (const auto& d : cv.decisions) {
      ModelTotals& m = byModel[d.model];
      m.truth += d.truthPoints, m.reached += d.truthReached;
      m.chosen += d.chosenPoints;
      m.edits += d.edits;
      m.trueCountEdits += d.trueCountEdits;
      // A true point no candidate reaches is an addition whatever the decision chooses.
      m.unreachableAdditions += std::min(d.edits.additions, d.truthPoints - d.truthReached);
      if (!std::isfinite(d.bestPointError)) continue;
      ++m.decisions;
      m.first += d.bestPointError, m.nearest += d.nearestCandidateError;
      const bool far = d.bestPointError > kMatchRadiusMeters;
      m.farFirst += far;
      m.farFirstReachable += far && d.nearestCandidateError <= kMatchRadiusMeters;
    }
    md << "\n## Per model\n\nOver the held-out decisions with true points: true points a candidate "
       << "reaches within 5 cm; the first chosen point's and the nearest candidate's error, mean "
          "cm; "
       << "decisions whose first point is more than 5 cm off, and of them those with a candidate "
       << "within 5 cm (the ranking failed, not the candidates); points chosen, and the edits "
       << "by kind over every held-out decision, with the additions of true points no candidate "
       << "reaches (no choice saves those); the edits with the true number of points (the same "
          "ranking cut there).\n\n"
       << "| model | decisions | true points reached | first point | nearest candidate | first "
          "point off | of them reachable | chosen | drags | additions (unreachable) | deletions "
          "| edits | with the true count |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& [model, m] : byModel) {
      const double n = static_cast<double>(std::max<std::size_t>(m.decisions, 1));
      md << "| " << model << " | " << m.decisions << " | " << m.reached << " of " << m.truth
         << " | " << reportCell(100 * m.first / n, "%.1f") << " | "
         << reportCell(100 * m.nearest / n, "%.1f") << " | " << m.farFirst << " | "
         << m.farFirstReachable << " | " << m.chosen << " | " << m.edits.drags << " | "
         << m.edits.additions << " (" << m.unreachableAdditions << ") | " << m.edits.deletions
         << " | " << m.edits.total() << " | " << m.trueCountEdits.total() << " |\n";
    }
    std::vector<const HeldOutDecision*> costly;
    for (const auto& d : cv.decisions) costly.push_back(&d);
    std::stable_sort(costly.begin(), costly.end(), [](const auto* a, const auto* b) {
      return a->edits.total() > b->edits.total();
    });
    costly.resize(std::min<std::size_t>(costly.size(), kCostliestDecisions));
    md << "\n## The costliest decisions\n\nPer object and model, as the scorer fitted without its "
       << "source chose (every one in scorer_cv.json, `held_out_decisions`). Best point: the first "
       << "chosen point's error; nearest candidate: the least error any one candidate had, cm.\n\n"
       << "| source | object | model | true points | chosen | drags | additions | deletions | "
          "best point | nearest candidate |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto* d : costly)
      md << "| " << d->source << " | " << d->object << " | " << d->model << " | " << d->truthPoints
         << " | " << d->chosenPoints << " | " << d->edits.drags << " | " << d->edits.additions
         << " | " << d->edits.deletions << " | " << reportCell(100 * d->bestPointError, "%.1f")
         << " | " << reportCell(100 * d->nearestCandidateError, "%.1f") << " |\n";
  }
  if (cv.confidence) {
    const ConfidenceCalibration& c = *cv.confidence;
    md << "\n## Object confidence, out of sample\n\n"
       << "Fitted on the " << c.objects << " curated objects' points as decided above (right with "
       << "one key: " << reportCell(100 * c.oneKeyShare, "%.0f %%") << "): P = sigmoid("
       << reportCell(c.intercept, "%.2f") << " + " << reportCell(c.slope, "%.2f")
       << " x exp(-d / 0.02)), d the least sure point's predicted distance. How well the signal "
       << "orders the objects: " << reportCell(signalAuc(cv), "%.2f")
       << " (AUC: the share of (right, wrong) object pairs where the right one's point is surer)."
       << "\n\n| accept automatically above | objects | right among them |\n|---|---|---|\n";
    std::vector<double> p;
    for (double d : cv.leastSure) p.push_back(c.probability(d));
    for (double threshold : {0.3, 0.5, 0.7, 0.9}) {
      const AutoAcceptRow row = autoAcceptAt(p, cv.oneKey, threshold);
      md << "| " << reportCell(threshold, "%.1f") << " | "
         << reportCell(100 * row.coverage, "%.0f %%") << " | "
         << reportCell(100 * row.precision, "%.0f %%") << " |\n";
    }
  }
  if (!cv.unseenConfidence.empty()) {
    md << "\nOn the " << cv.unseenObjects << " objects of the sources not tuned on (right with one "
       << "key: " << reportCell(100 * cv.unseenOneKeyShare, "%.0f %%")
       << "), maps not fitted on them:\n\n| object confidence | log loss | Brier | mean P |\n"
       << "|---|---|---|---|\n";
    for (const auto& c : cv.unseenConfidence)
      md << "| " << c.map << " | " << reportCell(c.logLoss, "%.3f") << " | "
         << reportCell(c.brier, "%.3f") << " | " << reportCell(c.meanProbability, "%.2f") << " |\n";
  }
  return md.str();
}

nlohmann::json toJson(const std::vector<HeldOutDecision>& held) {
  nlohmann::json decisions = nlohmann::json::array();
  for (const auto& d : held)
    decisions.push_back({{"source", d.source},
                         {"object", d.object},
                         {"model", d.model},
                         {"truth_points", d.truthPoints},
                         {"truth_reached", d.truthReached},
                         {"chosen_points", d.chosenPoints},
                         {"drags", d.edits.drags},
                         {"additions", d.edits.additions},
                         {"deletions", d.edits.deletions},
                         {"best_point_error_m", d.bestPointError},
                         {"nearest_candidate_error_m", d.nearestCandidateError}});
  return decisions;
}

nlohmann::json toJson(const ScorerCrossValidation& cv) {
  nlohmann::json folds = nlohmann::json::array();
  for (const auto& f : cv.folds)
    folds.push_back({{"source", f.source},
                     {"objects", f.objects},
                     {"count", toJson(f.count)},
                     {"generated_only", toJson(f.generatedOnly)},
                     {"with_curated", toJson(f.withCurated)},
                     {"true_count", toJson(f.trueCount)}});
  const nlohmann::json decisions = toJson(cv.decisions);
  nlohmann::json maps = nlohmann::json::array();
  for (const auto& c : cv.unseenConfidence)
    maps.push_back({{"map", c.map},
                    {"log_loss", c.logLoss},
                    {"brier", c.brier},
                    {"mean_probability", c.meanProbability}});
  const nlohmann::json unseenConfidence = {
      {"objects", cv.unseenObjects}, {"one_key_share", cv.unseenOneKeyShare}, {"maps", maps}};
  nlohmann::json curve = nlohmann::json::array();
  for (std::size_t k = 0; k < cv.ks.size(); ++k)
    curve.push_back({{"k", cv.ks[k]},
                     {"all", toJson(cv.curve[k])},
                     {"unseen", toJson(cv.unseenCurve[k])}});
  return {{"real_objects", cv.realObjects},
          {"tuned_on", cv.tunedOn},
          {"learning_curve", curve},
          {"learning_curve_draws", cv.draws},
          {"unseen",
           {{"count", toJson(cv.unseenCount)},
            {"generated_only", toJson(cv.unseenGeneratedOnly)},
            {"with_curated", toJson(cv.unseenWithCurated)},
            {"true_count", toJson(cv.unseenTrueCount)}}},
          {"generated_objects", cv.generatedObjects},
          {"candidate_recall", cv.candidateRecall},
          {"folds", folds},
          {"held_out_decisions", decisions},
          {"objects",
           {{"least_sure_distance", cv.leastSure},
            {"one_key", cv.oneKey},
            {"source", cv.objectSources},
            {"signal_auc", signalAuc(cv)}}},
          {"confidence", cv.confidence ? toJson(*cv.confidence) : nlohmann::json()},
          {"unseen_confidence", unseenConfidence},
          {"all",
           {{"count", toJson(cv.count)},
            {"generated_only", toJson(cv.generatedOnly)},
            {"with_curated", toJson(cv.withCurated)},
            {"true_count", toJson(cv.trueCount)}}}};
}

}  // namespace sagrid
