// Exact Euclidean distance transform on an N^3 voxel grid (Felzenszwalb & Huttenlocher 2012,
// "Distance Transforms of Sampled Functions"): for every voxel, the distance in voxels from its
// centre to the centre of the nearest voxel of a set. Linear time in the number of voxels.
#pragma once

#include <cstdint>
#include <vector>

namespace sagrid {

// `inside` holds 0/1 per voxel in VoxelGrid's linear order ([x][y][z], z fastest). Returns the
// distance (voxels) to the nearest voxel with inside = 1, 0 on those voxels; +inf everywhere
// when no voxel is inside.
std::vector<float> distanceToVoxels(const std::vector<std::uint8_t>& inside, int resolution);

}  // namespace sagrid
