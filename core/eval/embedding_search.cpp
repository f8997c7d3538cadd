#include "core/eval/embedding_search.h"

#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/features/feature_grid.h"

namespace sagrid {

std::size_t embeddingSearchVoxel(const FeatureGrid& f, const std::vector<float>& mean,
                                 EmbeddingMetric metric) {
  if (f.voxels.empty()) throw InvalidArgument("embedding search: no occupied voxels");
  if (static_cast<int>(mean.size()) != f.channels)
    throw InvalidArgument("embedding search: the model card's affordance feature has " +
                          std::to_string(mean.size()) + " channels, the features " +
                          std::to_string(f.channels));
  double meanNorm = 0;
  for (float v : mean) meanNorm += v * v;
  meanNorm = std::sqrt(meanNorm);
  std::size_t best = 0;
  double bestScore = -std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < f.voxels.size(); ++v) {
    const float* x = f.featuresOf(v);
    double dot = 0, norm = 0, l2 = 0;
    for (int c = 0; c < f.channels; ++c) {
      dot += x[c] * mean[c];
      norm += x[c] * x[c];
      l2 += (x[c] - mean[c]) * (x[c] - mean[c]);
    }
    const double score =
        metric == EmbeddingMetric::Cosine
            ? (norm > 0 && meanNorm > 0 ? dot / (std::sqrt(norm) * meanNorm) : -1.0)
            : -l2;
    if (score > bestScore) bestScore = score, best = v;
  }
  return best;
}

}  // namespace sagrid
