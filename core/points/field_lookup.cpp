#include "core/points/field_lookup.h"

#include <algorithm>
#include <limits>

namespace sagrid {

DenseField::DenseField(const std::vector<VoxelIndex>& voxels, int resolution)
    : m_n(resolution), m_index(static_cast<std::size_t>(m_n) * m_n * m_n, -1) {
  for (std::size_t v = 0; v < voxels.size(); ++v) {
    const auto& x = voxels[v];
    if (inside(x)) m_index[linear(x)] = static_cast<int>(v);
  }
}

float nearbyDistance(const PredictedField& field, const DenseField& dense, const VoxelIndex& centre,
                     int radius) {
  float best = std::numeric_limits<float>::infinity();
  for (int a = -radius; a <= radius; ++a)
    for (int b = -radius; b <= radius; ++b)
      for (int c = -radius; c <= radius; ++c) {
        const int at = dense.at({centre.i + a, centre.j + b, centre.k + c});
        if (at >= 0) best = std::min(best, field.distances[static_cast<std::size_t>(at)]);
      }
  return best;
}

}  // namespace sagrid
