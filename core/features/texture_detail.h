// Sub-voxel texture detail: how much the surface's own colour varies inside each voxel, read from
// the textures at many points of every surface piece — detail the embedded backend's 96^2 views
// and its one albedo sample per piece average away (the painted outline of a glass cooking zone or
// a printed touch control is a few millimetres wide; a voxel of a 60 cm hob is 9 mm).
#pragma once

#include <string>
#include <vector>

#include "core/grid/voxel_grid.h"

namespace sagrid {

struct Mesh;

constexpr int kTextureDetailChannels = 2;

// "texture_variation": 2 x the area-weighted standard deviation of luminance over the voxel's
// surface samples; "texture_edges": 4 x the mean luminance step between neighbouring samples.
// Both clamped to [0, 1]; 0 for a voxel of one flat colour.
std::vector<std::string> textureDetailChannelNames();

// Occupied voxels (grid.occupiedVoxels() order) x kTextureDetailChannels. `normalizedMesh` is the
// mesh `grid` was voxelized from. Each piece is fanned into triangles and every triangle sampled
// on a barycentric lattice of `lattice` steps per side (lattice (lattice + 1) / 2 samples).
std::vector<float> textureDetail(const Mesh& normalizedMesh, const VoxelGrid& grid,
                                 int lattice = 6);

}  // namespace sagrid
