// How many points one model has on an object, learned (issue 40): boosted trees over a
// description of the object's candidates under the first look (core/points/
// candidate_classifier.h) followed by a number k, giving the probability that the object has k
// points or more; the trees are monotone in k, so that probability never rises with k.
// Its trees learn on first looks of trees that did not see the object (the second look's folds),
// so they read the first look as it reads an object nobody curated.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/points/boosted_trees.h"
#include "core/points/point_candidates.h"

namespace sagrid {

inline constexpr std::size_t kMaxLearnedCount = 12;

// The names of the trees' inputs: countFeatures' values, withOtherModels' and "k".
const std::vector<std::string>& countFeatureNames();
// The object's description: the count's number of points, the number of candidates, the first
// look's probabilities of its ranking (best first, none within `nmsRadius` of a better one, as
// PointChoice suppresses), their sum and how many are likely, and the copies of the best.
// `firstLook` has one probability per candidate (InvalidArgument otherwise).
std::vector<float> countFeatures(const std::vector<PointCandidate>& candidates,
                                 const std::vector<float>& firstLook, float nmsRadius);
// An object's models of one category count parts that come together (a knob per burner, a
// handle beside a spout): the trees also read, from the countFeatures of the object's other
// models of the category under their own decisions' first looks, the count's number of points,
// the probabilities' sum and how many are at least 0.5 and 0.25, summed over those models (zeros
// where there are none). `own` is countFeatures' result; the result is what the trees read
// before k.
std::vector<float> withOtherModels(std::vector<float> own,
                                   const std::vector<std::vector<float>>& others);
// The rows the trees read for k = 1 .. kMaxLearnedCount: the features followed by k.
std::vector<std::vector<float>> countRows(const std::vector<float>& features);
// The probability that the object has k points or more (k >= 1; 0 beyond kMaxLearnedCount).
float countAtLeast(const BoostedTrees& trees, const std::vector<float>& features, std::size_t k);

// A choice (`taken`, candidate indices) with more of `ranking` (candidate indices best first) for
// as long as each is worth its risk. With n points taken, the next candidate not within
// `nmsRadius` of one joins when its probability `p` and the learned probability that the object
// has n + 1 points or more sum past one: a point too many is a deletion for the curator, while on
// an object with more points it is a match (an addition saved) or a drag (in place of an
// addition), so the expected edits fall by p - (1 - P(count >= n + 1)). Stops at the first that
// does not.
std::vector<std::size_t> withLearnedCount(std::vector<std::size_t> taken,
                                          const std::vector<std::size_t>& ranking,
                                          const std::vector<float>& p,
                                          const std::vector<PointCandidate>& candidates,
                                          float nmsRadius, const BoostedTrees& trees,
                                          const std::vector<float>& features);

}  // namespace sagrid
