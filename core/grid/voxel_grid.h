// The N^3 voxel grid over the normalized unit cube [-0.5, 0.5]^3 (64^3 by default).
// Voxel (i, j, k) has centre ((i + 0.5) / N - 0.5, (j + 0.5) / N - 0.5, (k + 0.5) / N - 0.5);
// the linear index is (i * N + j) * N + k (x slowest, z fastest, as a C-order [x][y][z] array).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sagrid {

constexpr int kDefaultGridResolution = 64;

struct VoxelIndex {
  int i = 0, j = 0, k = 0;
  bool operator==(const VoxelIndex& o) const { return i == o.i && j == o.j && k == o.k; }
  bool operator<(const VoxelIndex& o) const {
    return i != o.i ? i < o.i : (j != o.j ? j < o.j : k < o.k);
  }
};

inline Eigen::Vector3f voxelCenter(const VoxelIndex& v, int resolution) {
  const float n = static_cast<float>(resolution);
  return {(v.i + 0.5f) / n - 0.5f, (v.j + 0.5f) / n - 0.5f, (v.k + 0.5f) / n - 0.5f};
}

// The voxel containing a normalized-frame point, clamped into the grid.
VoxelIndex voxelContaining(const Eigen::Vector3f& normalizedPoint, int resolution);

// Occupancy of an N^3 grid: dense bit per voxel plus the sorted list of occupied voxels.
class VoxelGrid {
 public:
  explicit VoxelGrid(int resolution = kDefaultGridResolution);

  int resolution() const { return m_resolution; }
  std::size_t voxelCount() const { return m_occupancy.size(); }
  std::size_t linearIndex(const VoxelIndex& v) const {
    return (static_cast<std::size_t>(v.i) * m_resolution + v.j) * m_resolution + v.k;
  }
  VoxelIndex fromLinear(std::size_t index) const;
  bool contains(const VoxelIndex& v) const {
    return v.i >= 0 && v.j >= 0 && v.k >= 0 && v.i < m_resolution && v.j < m_resolution &&
           v.k < m_resolution;
  }

  bool occupied(const VoxelIndex& v) const { return m_occupancy[linearIndex(v)] != 0; }
  void setOccupied(const VoxelIndex& v);
  const std::vector<std::uint8_t>& occupancy() const { return m_occupancy; }  // 0/1 per voxel

  // Occupied voxels in increasing linear index order.
  std::vector<VoxelIndex> occupiedVoxels() const;
  std::size_t occupiedCount() const { return m_occupiedCount; }

 private:
  int m_resolution;
  std::vector<std::uint8_t> m_occupancy;
  std::size_t m_occupiedCount = 0;
};

}  // namespace sagrid
