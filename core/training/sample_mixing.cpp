#include "core/training/sample_mixing.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/common/error.h"

namespace sagrid {

std::vector<double> mixedSampleWeights(const std::vector<std::size_t>& sizes,
                                       const std::vector<double>& weights) {
  if (sizes.size() != weights.size())
    throw InvalidArgument("mixed data: " + std::to_string(weights.size()) + " weights for " +
                          std::to_string(sizes.size()) + " datasets");
  std::vector<double> perSample;
  double total = 0;
  for (std::size_t d = 0; d < sizes.size(); ++d) {
    if (!(weights[d] >= 0))
      throw InvalidArgument("mixed data: dataset " + std::to_string(d + 1) +
                            " has a negative sampling weight");
    for (std::size_t i = 0; i < sizes[d]; ++i)
      perSample.push_back(weights[d] / static_cast<double>(sizes[d]));
    if (sizes[d] > 0) total += weights[d];
  }
  if (total <= 0)
    throw InvalidArgument("mixed data: no dataset with objects has a positive sampling weight");
  return perSample;
}

std::vector<std::size_t> drawEpochOrder(std::size_t count, const std::vector<double>& sampleWeights,
                                        std::mt19937& rng) {
  std::vector<std::size_t> order(count);
  if (sampleWeights.empty()) {
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    return order;
  }
  std::discrete_distribution<std::size_t> pick(sampleWeights.begin(), sampleWeights.end());
  for (auto& o : order) o = pick(rng);
  return order;
}

}  // namespace sagrid
