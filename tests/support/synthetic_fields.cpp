#include "support/synthetic_fields.h"

#include <algorithm>
#include <random>

namespace sagrid::test {

PredictedField plateField(const std::vector<Eigen::Vector3f>& centres, float noise,
                          unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-noise, noise);
  PredictedField f;
  f.resolution = kPlateResolution;
  for (int i = 0; i < kPlateResolution; ++i)
    for (int j = 0; j < kPlateResolution; ++j) {
      const VoxelIndex v{i, j, 10};
      float best = 1e9f;
      for (const auto& c : centres)
        best = std::min(best, (voxelCenter(v, kPlateResolution) - c).norm());
      f.voxels.push_back(v);
      f.distances.push_back(std::max(0.0f, best + jitter(rng)));
    }
  return f;
}

Eigen::Vector3f onPlate(int i, int j) { return voxelCenter({i, j, 10}, kPlateResolution); }

}  // namespace sagrid::test
