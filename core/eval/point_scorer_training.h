// Fitting the learned point decision (core/annotate/point_scorer.h) on candidate sets
// (core/eval/candidate_sets.h) from generated and curated real objects, and measuring it leave one
// source out: for each source of curated real objects (a wild-pool repository, a Sweet Home 3D
// library, real-dev), a decision fitted on every other source (and on the generated objects) is
// measured on that source's objects, beside the count's points and beside a decision fitted on
// generated objects alone. Figures are the curator's edits, the share right with one key and the
// single-point error (the best point's distance to the nearest ground truth), as `sagrid eval`
// counts them.
#pragma once

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/annotate/object_confidence.h"
#include "core/annotate/point_scorer.h"
#include "core/common/paired_change.h"
#include "core/eval/candidate_sets.h"
#include "core/eval/curator_effort.h"

namespace sagrid {

// The point decision's boosting: the defaults, each tree allowed half of the features.
inline BoostingOptions halfTheFeaturesPerTree() {
  BoostingOptions boosting;
  boosting.featureShare = 0.5f;
  return boosting;
}

struct ScorerTrainingOptions {
  // A curated real object's candidates weigh this many generated objects' (as the category
  // classifier weighs curated objects, kCuratedCategoryWeight).
  float realWeight = 3;
  double ridge = 1.0;
  // Boosted trees; false: the logistic regression. Leave one source out on the 30 unseen curated
  // objects, trees over the bare count's candidates needed 0.72 edits per hand point, the logistic
  // regression 0.82.
  bool trees = true;
  // With trees: a second look in the company of the object's other candidates
  // (CandidateClassifier::contextTrees).
  bool context = true;
  // Each tree may split on a random half of the candidate's features, drawn per tree
  // (BoostingOptions::featureShare). Leave one source out over 20 paired repeats, 0.537 -> 0.522
  // edits per hand point (fewer in 13, more in 6), the 13 repositories no rule was made on 0.576
  // -> 0.555 (fewer in 15, more in 4), best point 7.2 -> 6.5 cm (resources/models/README.md,
  // session 53).
  BoostingOptions boosting = halfTheFeaturesPerTree();
  // The choice (core/points/candidate_classifier.h), per model the one of these that minimises
  // the training objects' weighted edits (the first on ties: keep the count's points, add none).
  std::vector<float> keepThresholds = {0.0f, 0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
  // Down to 0.1: the geometric mean of two looks (CandidateClassifier::contextTrees) puts a point
  // the first look missed and the second found near 0.3 (0.593 -> 0.585 edits per hand point
  // leave one source out, resources/models/README.md).
  std::vector<float> addThresholds = {1.01f, 0.9f, 0.8f, 0.7f, 0.6f, 0.5f, 0.4f, 0.3f, 0.2f, 0.1f};
  std::vector<float> nmsRadii = {0.03f, 0.05f, 0.08f, 0.12f};
  // PointChoice::copyThreshold; the first (none) on ties.
  std::vector<float> copyThresholds = {1.01f, 0.2f, 0.05f, 0.0f};
  // The choice judged by the mean training cost of it and its neighbours in the keep and add
  // thresholds (a flat minimum rather than a lucky one; core/eval/choice_grid.h). Leave one source
  // out over 20 paired repeats, 0.583 -> 0.567 edits per hand point (fewer in 15, more in 4;
  // resources/models/README.md, session 44).
  bool smoothChoice = true;
  // With trees and the second look: a learned count (core/points/point_count.h) that adds the
  // ranking's next candidates to the choice while each is worth its risk. Leave one source out
  // over 20 paired repeats, 0.567 -> 0.547 edits per hand point (fewer in 19, more in none; the
  // 13 repositories no rule was made on fewer in 16, more in 3; resources/models/README.md,
  // session 46).
  bool learnedCount = true;
  // The learned count also reads the object's other models of its category (a knob per burner;
  // core/points/point_count.h, withOtherModels).
  bool otherModelsCount = true;
  // Leave out of training each object's candidates of a model whose true points no candidate
  // reaches (a hob's zones printed on a flat box): every candidate is then a non-point, and the
  // trees would learn that what looks most like a point is not one.
  bool skipUnreached = false;
};

// One decision per model with both points and non-points among `sets`' candidates (other models
// get none: their count's points stand). Throws InvalidArgument when no model has.
PointScorer trainPointScorer(const std::vector<const CandidateSet*>& sets,
                             const ScorerTrainingOptions& options);

// The figures of one way of choosing points over some objects.
struct PointChoiceFigures {
  CuratorEffort effort;
  PointEdits edits;          // summed over the objects
  double singleError = 0;    // metres, mean over (object, model) pairs with ground truth
  std::size_t singleErrors = 0;
  // The curator's edits per point placed by hand (NaN without ground-truth points).
  double editsPerHandPoint() const;
};
nlohmann::json toJson(const PointChoiceFigures& figures);

struct ScorerSourceFold {
  std::string source;
  std::size_t objects = 0;
  PointChoiceFigures count, generatedOnly, withCurated;
  // withCurated's ranking cut at each decision's true number of points (its suppression radius
  // kept, thresholds and copies off): what a perfect count decision would leave to the curator.
  PointChoiceFigures trueCount;
  // Per ScorerCurveOptions::ks: fitted on the generated objects and k curated objects drawn from
  // the other sources (pooled over ScorerCurveOptions::draws draws).
  std::vector<PointChoiceFigures> curve;
};

struct ScorerCurveOptions {
  std::vector<std::size_t> ks;  // curated objects of the other sources in training (learning curve)
  unsigned seed = 1;            // of the draws
  // Draws of the k objects per fold; a fold's curve pools them (the same objects decided once
  // per draw). One draw is noisy: a lucky or unlucky pick of a few objects moves the curve.
  unsigned draws = 1;
  // Sources a pass or rule was made on: the report gives the figures without them too, and an
  // object confidence fitted on their objects alone is checked on the others.
  std::vector<std::string> tunedOn;
  // Another object confidence (e.g. a models folder's confidence.json) checked on the same
  // objects, named in the report.
  std::optional<ConfidenceCalibration> otherConfidence;
  std::string otherConfidenceName;
};

// How well an object confidence predicts "right with one key" on objects it was not fitted on.
struct ConfidenceCheck {
  std::string map;  // which calibration
  double logLoss = 0, brier = 0, meanProbability = 0;
};

// One model's points on one curated object as the scorer fitted without its source chose them.
struct HeldOutDecision {
  std::string source, object, model;
  std::size_t truthPoints = 0, chosenPoints = 0;
  std::size_t truthReached = 0;  // true points with a candidate within the match radius
  PointEdits edits;
  PointEdits trueCountEdits;  // the same ranking cut at the true number of points
  double bestPointError = NAN;         // metres: the first chosen point to the nearest truth
  double nearestCandidateError = NAN;  // metres: the best any one candidate could have done
};

struct ScorerCrossValidation {
  std::vector<ScorerSourceFold> folds;  // one per source of curated real objects
  std::vector<HeldOutDecision> decisions;  // every held-out (object, model), folds in order
  PointChoiceFigures count, generatedOnly, withCurated;  // over every fold's objects
  PointChoiceFigures trueCount, unseenTrueCount;  // ScorerSourceFold::trueCount, totalled
  // The same over the folds of sources not in ScorerCurveOptions::tunedOn.
  PointChoiceFigures unseenCount, unseenGeneratedOnly, unseenWithCurated;
  std::vector<std::string> tunedOn;
  std::vector<std::size_t> ks;
  unsigned draws = 1;
  std::vector<PointChoiceFigures> curve, unseenCurve;  // per k, over the folds (and draws)
  double candidateRecall = 0;  // share of ground-truth points with a candidate within 5 cm
  std::size_t generatedObjects = 0, realObjects = 0;
  // Per curated object, its points decided by the scorer fitted without its source: annotate's
  // object-confidence signal (the least sure chosen point's predicted distance) and whether it is
  // right with one key; and the object confidence fitted on them (core/annotate/
  // object_confidence.h) — out of sample as far as the points go: no object's points were chosen
  // by a scorer that saw it.
  std::vector<double> leastSure;
  std::vector<bool> oneKey;
  std::vector<std::string> objectSources;  // each object's source, in the same order
  std::optional<ConfidenceCalibration> confidence;
  // With tunedOn: on the objects of the other sources (unseenObjects of them, unseenOneKeyShare
  // right with one key), the confidence fitted on the tuned-on sources' objects alone, then
  // ScorerCurveOptions::otherConfidence; neither was fitted on them.
  std::vector<ConfidenceCheck> unseenConfidence;
  std::size_t unseenObjects = 0;
  double unseenOneKeyShare = 0;
};

// Throws InvalidArgument when fewer than two sources of real objects are in `sets`.
ScorerCrossValidation crossValidatePointScorer(const std::vector<CandidateSet>& sets,
                                               const ScorerTrainingOptions& options,
                                               const ScorerCurveOptions& curve = {});

// A guarded scorer update: the new scorer's decision for a model is adopted only where it makes
// the edits on the held-out curated objects fewer than the current one (the models folder's
// scorer; where it has none for a model, the points the held-out candidates were made with: the
// count's). A category's decisions read each other (each model's count reads the category's other
// models: a knob per burner), so they are judged together: every mix of the category's current
// and new decisions is judged on the category's held-out objects as a whole, and the mix with the
// fewest edits is adopted (on ties the one with fewer new decisions, the current ones first)
// where it saves more edits than the noise of the per-object differences from the current
// decisions (core/common/paired_change.h; else the current ones stay): what is adopted is what
// was judged. A model without held-out objects keeps its current decision
// (nothing judged it). The passes the decisions switch off are the same for both (the guard
// checks), so decisions of two scorers can stand side by side in one file (adoptedScorer).
struct ScorerVerdict {
  std::string model;
  // The model's held-out edits with the current decisions and with the new scorer's.
  std::size_t currentEdits = 0, newEdits = 0, handPoints = 0;
  bool adopted = false;  // its new decision is in the category's adopted mix
  // Its category's held-out edits with the current decisions and with the mix adopted, and how
  // many of the category's models were judged.
  std::size_t categoryCurrentEdits = 0, categoryAdoptedEdits = 0, categoryJudged = 0;
  // The standard error of the category's change in edits (summed over its objects): its best mix
  // is adopted only where it saves more edits than that (NaN for fewer than two objects).
  double categoryNoise = NAN;
};
struct ScorerGuard {
  std::vector<ScorerVerdict> byModel;  // the held-out objects' models, then the new scorer's others
  std::size_t currentEdits = 0, newEdits = 0;
  std::size_t adoptedEdits = 0;  // with the decisions adopted (each category's mix, judged)
  bool adopted = false;          // for at least one model
  bool adoptedWhole() const;     // for every model judged, and the new scorer has no other
  // Per category, each held-out object's edits with the current decisions and with all the new
  // ones (the guard by source pairs them over its folds).
  std::map<std::string, std::vector<ObjectFigures>> categoryEdits;
};
// `current` may be null (no scorer yet). Throws InvalidArgument when `heldOut` has no candidate
// set, when a held-out object is also in `training` (same source and id), or when the held-out
// candidates, the new scorer and the current one were made with different passes.
ScorerGuard guardPointScorer(const PointScorer* current, const PointScorer& fresh,
                             const std::vector<CandidateSet>& heldOut,
                             const std::vector<const CandidateSet*>& training);
nlohmann::json toJson(const ScorerGuard& guard);

// What `guard` adopts: `current`'s decisions (none when null) with, for every model it adopted,
// `fresh`'s (where `fresh` has none for that model, none: the count's points win there). Its
// passes off and record are `fresh`'s, the record naming the models adopted when not all were.
PointScorer adoptedScorer(const PointScorer* current, const PointScorer& fresh,
                          const ScorerGuard& guard);
// The category of a model's name (stove of stove.heatsource): a category's decisions are judged
// together.
std::string categoryOfModel(const std::string& model);
// The models of `guard` whose new decision was (`adopted`) or was not adopted, comma-separated.
std::string modelsWhere(const ScorerGuard& guard, bool adopted);
// One verdict as the CLI and the GUI show it: "model: a -> b edits on n held-out points: adopted"
// (or "the decision before stays"), where other models of its category were judged too followed
// by " (stove judged as a whole: c -> d edits with the decisions adopted)".
std::string toString(const ScorerVerdict& verdict);

// How well the object-confidence signal orders cv's objects: the share of (right, wrong) pairs in
// which the right object's least sure point has the smaller predicted distance (ties count half);
// NaN without both kinds.
double signalAuc(const ScorerCrossValidation& cv);

std::string scorerCrossValidationMarkdown(const ScorerCrossValidation& cv);
// scorer_cv.json's `held_out_decisions`: one object per decision.
nlohmann::json toJson(const std::vector<HeldOutDecision>& decisions);
nlohmann::json toJson(const ScorerCrossValidation& cv);

}  // namespace sagrid
