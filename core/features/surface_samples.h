// Per-voxel statistics of the surface itself (not of the views): area, area-weighted albedo and
// the normal structure tensor. Exact: every triangle is clipped against the voxels it crosses
// (slab by slab, so the cost follows the voxels touched), and the albedo of each piece is taken
// at the piece's centroid.
#pragma once

#include <array>
#include <vector>

#include "core/grid/voxel_grid.h"

namespace sagrid {

struct Mesh;

struct VoxelSurfaceStats {
  float area = 0.0f;                     // normalized-frame surface area inside the voxel
  std::array<float, 3> albedo{0, 0, 0};  // area-weighted sum (divide by area)
  std::array<float, 6> normalTensor{0, 0, 0,
                                    0, 0, 0};  // area-weighted sum of n n^T: xx yy zz xy xz yz
};

// One entry per occupied voxel of `grid`, in grid.occupiedVoxels() order. `normalizedMesh` is the
// mesh `grid` was voxelized from. A face lying exactly on a voxel boundary counts in both voxels.
std::vector<VoxelSurfaceStats> voxelSurfaceStats(const Mesh& normalizedMesh, const VoxelGrid& grid);

// Linear voxel index -> position in grid.occupiedVoxels(), -1 for empty voxels.
std::vector<int> occupiedSlots(const VoxelGrid& grid);

}  // namespace sagrid
