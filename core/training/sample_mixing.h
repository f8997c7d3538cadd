// Drawing training samples from several datasets at once (fine-tuning on new data beside a replay
// of the data a model was trained on). Per draw: a dataset in proportion to its weight, then one
// of its objects uniformly; that is a per-sample weight of w_d / n_d. Plain C++, seeded.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace sagrid {

// Per-sample weights for datasets of `sizes` objects (in order, concatenated) drawn with
// `weights`. Throws InvalidArgument for mismatched lengths, a negative weight, or no dataset with
// both objects and a positive weight.
std::vector<double> mixedSampleWeights(const std::vector<std::size_t>& sizes,
                                       const std::vector<double>& weights);

// One epoch's sample order over `count` samples: empty `sampleWeights` = a shuffled permutation
// (each sample once); else `count` draws with replacement in proportion to the weights, so an
// epoch costs the same number of steps as one pass over all datasets.
std::vector<std::size_t> drawEpochOrder(std::size_t count, const std::vector<double>& sampleWeights,
                                        std::mt19937& rng);

}  // namespace sagrid
