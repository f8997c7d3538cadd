// Per-voxel statistics of the surface itself (not of the views): area, area-weighted albedo and
// the normal structure tensor, from stratified point samples on every triangle (a few samples per
// voxel face, so large flat triangles are spread over all the voxels they cross).
#pragma once

#include <array>
#include <vector>

#include "core/grid/voxel_grid.h"

namespace sagrid {

struct Mesh;

struct VoxelSurfaceStats {
  float area = 0.0f;                        // normalized-frame surface area inside the voxel
  std::array<float, 3> albedo{0, 0, 0};     // area-weighted sum (divide by area)
  std::array<float, 6> normalTensor{0, 0, 0, 0, 0, 0};  // area-weighted sum of n n^T: xx yy zz xy xz yz
};

// One entry per occupied voxel of `grid`, in grid.occupiedVoxels() order. `normalizedMesh` is the
// mesh `grid` was voxelized from. samplesPerVoxelFace sets the sampling density.
std::vector<VoxelSurfaceStats> voxelSurfaceStats(const Mesh& normalizedMesh, const VoxelGrid& grid,
                                                 float samplesPerVoxelFace = 4.0f);

// Linear voxel index -> position in grid.occupiedVoxels(), -1 for empty voxels.
std::vector<int> occupiedSlots(const VoxelGrid& grid);

}  // namespace sagrid
