// Neighbour tables of submanifold sparse convolution: for each occupied voxel and each kernel tap
// (dilation respected), the row of the neighbouring occupied voxel, or `missing` when that
// neighbour is empty or outside the grid. Computed once per object (and augmentation) and shared
// by every layer with the same kernel and dilation. Plain C++, no torch.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid/voxel_grid.h"

namespace sagrid::model {

struct NeighborTable {
  int kernel = 3;
  int dilation = 1;
  std::int64_t voxelCount = 0;
  // voxelCount * taps entries, row-major (voxel, tap); tap t = (a * kernel + b) * kernel + c is
  // the offset ((a - r) * dilation, (b - r) * dilation, (c - r) * dilation) along (i, j, k),
  // r = kernel / 2 — the same order as a Conv3d weight's (kD, kH, kW) flattened.
  std::vector<std::int64_t> rows;
  std::int64_t missing = -1;  // row index used for absent neighbours (the caller's zero row)

  int taps() const { return kernel * kernel * kernel; }
};

// `voxels` must be inside a resolution^3 grid and unique. Absent neighbours get `missingRow`.
NeighborTable buildNeighborTable(const std::vector<VoxelIndex>& voxels, int resolution, int kernel,
                                 int dilation, std::int64_t missingRow);

}  // namespace sagrid::model
