#include "support/synthetic_fields.h"

#include <algorithm>
#include <random>

namespace sagrid::test {

namespace {

PredictedField plate(const std::vector<Eigen::Vector3f>& centres, const std::vector<float>& offsets,
                     float noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-noise, noise);
  PredictedField f;
  f.resolution = kPlateResolution;
  for (int i = 0; i < kPlateResolution; ++i)
    for (int j = 0; j < kPlateResolution; ++j) {
      const VoxelIndex v{i, j, 10};
      float best = 1e9f;
      for (std::size_t c = 0; c < centres.size(); ++c)
        best = std::min(best, (voxelCenter(v, kPlateResolution) - centres[c]).norm() +
                                  (offsets.empty() ? 0.0f : offsets[c]));
      f.voxels.push_back(v);
      f.distances.push_back(std::max(0.0f, best + jitter(rng)));
    }
  return f;
}

}  // namespace

PredictedField plateField(const std::vector<Eigen::Vector3f>& centres, float noise, unsigned seed) {
  return plate(centres, {}, noise, seed);
}

PredictedField plateFieldWithOffsets(const std::vector<Eigen::Vector3f>& centres,
                                     const std::vector<float>& offsets) {
  return plate(centres, offsets, 0.0f, 1);
}

PredictedField fieldTowards(const FeatureGrid& grid, const std::vector<Eigen::Vector3f>& centres,
                            const std::vector<float>& offsets) {
  PredictedField f;
  f.resolution = grid.resolution;
  f.voxels = grid.voxels;
  for (const auto& v : grid.voxels) {
    const Eigen::Vector3f c = voxelCenter(v, grid.resolution);
    float best = 1e9f;
    for (std::size_t i = 0; i < centres.size(); ++i)
      best = std::min(best, (c - grid.normalization.toNormalized(centres[i])).norm() + offsets[i]);
    f.distances.push_back(best);
  }
  return f;
}

ExtractedPoint pointOnField(const PredictedField& field, const Eigen::Vector3f& p) {
  ExtractedPoint e;
  e.position = p;
  const VoxelIndex at = voxelContaining(p, field.resolution);
  for (std::size_t v = 0; v < field.voxels.size(); ++v)
    if (field.voxels[v] == at) e.distance = field.distances[v];
  e.confidence = 1.0f;
  return e;
}

Eigen::Vector3f onPlate(int i, int j) { return voxelCenter({i, j, 10}, kPlateResolution); }

std::vector<Eigen::Vector3f> fiveBurnersOnPlate() {
  return {onPlate(6, 6), onPlate(6, 25), onPlate(25, 6), onPlate(25, 25), onPlate(16, 16)};
}

float nearestExtracted(const std::vector<ExtractedPoint>& points, const Eigen::Vector3f& p) {
  float best = 1e9f;
  for (const auto& q : points) best = std::min(best, (q.position - p).norm());
  return best;
}

}  // namespace sagrid::test
