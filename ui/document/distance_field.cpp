#include "ui/document/distance_field.h"

#include <limits>

namespace sagrid::ui {

DistanceField distanceFieldFromPoints(const std::string& type,
                                      const std::vector<VoxelIndex>& voxels, int resolution,
                                      const Normalization& normalization,
                                      const std::vector<Eigen::Vector3f>& points) {
  DistanceField field;
  field.type = type;
  field.resolution = resolution;
  field.normalization = normalization;
  field.voxels = voxels;
  field.distances.resize(voxels.size());
  for (std::size_t i = 0; i < voxels.size(); ++i) {
    const Eigen::Vector3f c = field.center(i);
    float best = std::numeric_limits<float>::infinity();
    for (const auto& p : points) best = std::min(best, (c - p).norm());
    field.distances[i] = best;
  }
  return field;
}

std::vector<VoxelIndex> allVoxels(int resolution) {
  std::vector<VoxelIndex> voxels;
  voxels.reserve(std::size_t(resolution) * resolution * resolution);
  for (int i = 0; i < resolution; ++i)
    for (int j = 0; j < resolution; ++j)
      for (int k = 0; k < resolution; ++k) voxels.push_back({i, j, k});
  return voxels;
}

}  // namespace sagrid::ui
