// Surface voxelization: a voxel is occupied iff some triangle intersects its closed cube
// (exact triangle-box overlap test, so thin plates and small knobs are never lost).
#pragma once

#include "core/grid/voxel_grid.h"

namespace sagrid {

struct Mesh;

// `normalizedMesh` must already be in the normalized frame (see normalization.h). Triangles
// reaching outside [-0.5, 0.5]^3 occupy only the voxels inside the grid.
VoxelGrid voxelize(const Mesh& normalizedMesh, int resolution = kDefaultGridResolution);

}  // namespace sagrid
