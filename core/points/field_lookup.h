// Voxel lookups on a predicted field (core/points/point_extraction.h): which field entry a voxel
// of the grid is, and the smallest predicted distance near a voxel. Shared by the passes that add
// points after the automatic count (mirror pairs, repeated parts).
#pragma once

#include <cstddef>
#include <vector>

#include "core/points/point_extraction.h"

namespace sagrid {

// Index into the field's voxels per voxel of the N^3 grid (-1 = empty).
class DenseField {
 public:
  DenseField(const std::vector<VoxelIndex>& voxels, int resolution);
  bool inside(const VoxelIndex& v) const {
    return v.i >= 0 && v.j >= 0 && v.k >= 0 && v.i < m_n && v.j < m_n && v.k < m_n;
  }
  // Field index of a voxel, -1 when empty or outside the grid.
  int at(const VoxelIndex& v) const { return inside(v) ? m_index[linear(v)] : -1; }

 private:
  std::size_t linear(const VoxelIndex& v) const {
    return (static_cast<std::size_t>(v.i) * m_n + v.j) * m_n + v.k;
  }
  int m_n;
  std::vector<int> m_index;
};

// The smallest predicted distance within `radius` voxels (Chebyshev) of `centre` (infinity when
// none of them is occupied).
float nearbyDistance(const PredictedField& field, const DenseField& dense, const VoxelIndex& centre,
                     int radius);

}  // namespace sagrid
