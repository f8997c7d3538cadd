#include "core/grid/voxel_grid.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"

namespace sagrid {

VoxelIndex voxelContaining(const Eigen::Vector3f& normalizedPoint, int resolution) {
  auto axis = [resolution](float x) {
    const float g = std::floor((x + 0.5f) * static_cast<float>(resolution));
    if (!(g >= 0.0f)) return 0;  // also NaN
    return std::min(static_cast<int>(std::min(g, 1e9f)), resolution - 1);
  };
  return {axis(normalizedPoint.x()), axis(normalizedPoint.y()), axis(normalizedPoint.z())};
}

VoxelGrid::VoxelGrid(int resolution) : m_resolution(resolution) {
  if (resolution < 1 || resolution > 1024) {
    throw InvalidArgument("grid resolution must be between 1 and 1024, got " +
                          std::to_string(resolution));
  }
  m_occupancy.assign(static_cast<std::size_t>(resolution) * resolution * resolution, 0);
}

VoxelIndex VoxelGrid::fromLinear(std::size_t index) const {
  const std::size_t n = static_cast<std::size_t>(m_resolution);
  return {static_cast<int>(index / (n * n)), static_cast<int>((index / n) % n),
          static_cast<int>(index % n)};
}

void VoxelGrid::setOccupied(const VoxelIndex& v) {
  std::uint8_t& cell = m_occupancy[linearIndex(v)];
  m_occupiedCount += cell == 0;
  cell = 1;
}

std::vector<VoxelIndex> VoxelGrid::occupiedVoxels() const {
  std::vector<VoxelIndex> voxels;
  voxels.reserve(m_occupiedCount);
  for (std::size_t i = 0; i < m_occupancy.size(); ++i) {
    if (m_occupancy[i]) voxels.push_back(fromLinear(i));
  }
  return voxels;
}

}  // namespace sagrid
