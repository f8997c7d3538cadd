// Per-voxel statistics of the surface itself (not of the views): area, area-weighted albedo and
// the normal structure tensor. Exact: every triangle is clipped against the voxels it crosses
// (slab by slab, so the cost follows the voxels touched), and the albedo of each piece is taken
// at the piece's centroid.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
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

// One triangle's part inside one occupied voxel: a convex polygon (3 to 9 vertices, normalized
// frame) with its area and the triangle's unit normal.
struct SurfacePiece {
  int triangle = 0;
  int slot = 0;  // position of the voxel in grid.occupiedVoxels()
  const Eigen::Vector3f* vertices = nullptr;
  int vertexCount = 0;
  float area = 0.0f;
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
};

// Calls `visit` for every piece of positive area, clipping each triangle against the voxels it
// crosses slab by slab (the exact clipping voxelSurfaceStats uses).
void forEachSurfacePiece(const Mesh& normalizedMesh, const VoxelGrid& grid,
                         const std::function<void(const SurfacePiece&)>& visit);

// Barycentric (u, v) of `p` in triangle `triangle` of `mesh`: p = a + u (b - a) + v (c - a), for
// Mesh::albedo. `p` is assumed to lie in the triangle's plane.
Eigen::Vector2f barycentricIn(const Mesh& mesh, int triangle, const Eigen::Vector3f& p);

// Linear voxel index -> position in grid.occupiedVoxels(), -1 for empty voxels.
std::vector<int> occupiedSlots(const VoxelGrid& grid);

}  // namespace sagrid
