// Which of an object's point candidates (core/points/point_candidates.h) are affordances, and how
// many: a probability per candidate (a logistic regression over the candidates' standardized
// features, or boosted trees), then a greedy choice best first that edits the count's points: a
// kept point stays at or above one threshold, another candidate joins at or above a second, no
// two within a suppression radius, at least one. With the thresholds at 0 and above 1 the count's
// points stand, so a choice fitted to minimise edits starts from them.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/points/boosted_trees.h"
#include "core/points/point_candidates.h"

namespace sagrid {

// Boosted trees when `trees` is set, else the logistic regression (mean, scale, weights, bias).
struct CandidateClassifier {
  std::vector<float> mean, scale;  // per feature: x' = (x - mean) / scale
  std::vector<float> weights;      // per standardized feature
  float bias = 0;
  std::optional<BoostedTrees> trees;  // when set, the probability is theirs
  // A second look in the company of the object's other candidates (boosted trees over a
  // candidate's features followed by its contextFeatures under the first look's probabilities):
  // where set, candidateProbabilities gives the geometric mean of both looks.
  std::optional<BoostedTrees> contextTrees;
  // The probability that a candidate with these features is an affordance point (the first
  // look). Throws InvalidArgument when the feature count differs from the classifier's.
  float probability(const std::vector<float>& features) const;
};

// What a candidate's company says, given every candidate's first-look probability `p` on one
// object: its probability, against the object's best and its rank; how far it lies from the
// object's most probable candidate in height, facing and the shape of its part; and how much it
// looks like the other likely candidates (a burner among burners, a knob in a row). Repeated
// parts and rows become numbers the second look weighs. kContextFeatureCount per candidate,
// contextFeatureNames() order.
constexpr std::size_t kContextFeatureCount = 6;
const std::vector<std::string>& contextFeatureNames();
std::vector<std::vector<float>> contextFeatures(const std::vector<PointCandidate>& candidates,
                                                const std::vector<float>& p);
// The decision's probabilities given the first look's: the geometric mean of both looks.
std::vector<float> bothLooks(const BoostedTrees& contextTrees,
                             const std::vector<PointCandidate>& candidates,
                             const std::vector<float>& firstLook);
// A candidate's features followed by its context features.
std::vector<std::vector<float>> withContext(const std::vector<PointCandidate>& candidates,
                                            const std::vector<float>& p);

struct PointChoice {
  float keepThreshold = 0.5f;  // a kept point (PointCandidate::kept) at or above this stays
  float addThreshold = 0.5f;   // another candidate at or above this becomes a point
  float nmsRadius = 0.08f;     // normalized units: no point within this of a better one
  // A taken candidate brings those of its places on its part's copies (PointCandidate::copies)
  // at or above this (above 1: none), each unless a taken point lies within the radius.
  float copyThreshold = 1.01f;
};

// Candidates by `probability` (one per candidate), best first; each at or above its threshold is
// taken unless a taken one lies within the radius (two kept points do not suppress each other),
// followed by its copies' places at or above the copy threshold; when none is, the best alone
// (with its copies). Indices into `candidates`, in the order taken; empty for no candidates.
std::vector<std::size_t> chooseCandidates(const std::vector<float>& probability,
                                          const std::vector<PointCandidate>& candidates,
                                          const PointChoice& choice);
std::vector<float> candidateProbabilities(const CandidateClassifier& classifier,
                                          const std::vector<PointCandidate>& candidates);

// Weighted maximum-likelihood fit of the logistic regression. `rows` feature vectors of one length,
// `positive` their labels, `weight` each row's weight (> 0). Throws InvalidArgument for no rows,
// rows of different lengths or a class with no weight.
CandidateClassifier fitCandidateClassifier(const std::vector<std::vector<float>>& rows,
                                           const std::vector<bool>& positive,
                                           const std::vector<float>& weight, double ridge = 1.0);

}  // namespace sagrid
