// Which of an object's point candidates (core/points/point_candidates.h) are affordances, and how
// many: a probability per candidate (a logistic regression over the candidates' standardized
// features, or boosted trees), then a greedy choice best first that edits the count's points: a
// kept point stays at or above one threshold, another candidate joins at or above a second, no
// two within a suppression radius, at least one. With the thresholds at 0 and above 1 the count's
// points stand, so a choice fitted to minimise edits starts from them.
#pragma once

#include <cstddef>
#include <optional>
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
  // The probability that a candidate with these features is an affordance point. Throws
  // InvalidArgument when the feature count differs from the classifier's.
  float probability(const std::vector<float>& features) const;
};

struct PointChoice {
  float keepThreshold = 0.5f;  // a kept point (PointCandidate::kept) at or above this stays
  float addThreshold = 0.5f;   // another candidate at or above this becomes a point
  float nmsRadius = 0.08f;     // normalized units: no point within this of a better one
};

// Candidates by `probability` (one per candidate), best first; each at or above its threshold is
// taken unless a taken one lies within the radius (two kept points do not suppress each other);
// when none is, the best alone. Indices into
// `candidates`, best first; empty for no candidates.
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
