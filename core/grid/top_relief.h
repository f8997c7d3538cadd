// The relief of an object's top, seen from above on its occupied voxels: evidence of what it is
// that a global descriptor misses. A basin is a depression enclosed by the rim around it, burners
// and grates are many small raised or sunken spots on the upper part, an oven, a washing machine
// or a fridge is one flat lid. Computed on the height map (the highest occupied voxel of each
// column, z up) of the normalized grid, so it needs no units and is the same for any file frame.
#pragma once

#include <array>
#include <vector>

#include "core/grid/voxel_grid.h"

namespace sagrid {

inline constexpr int kTopReliefSize = 7;

// In order:
//  0 flat top: share of the footprint's columns within one voxel of the highest
//  1 basin: share of columns at least max(2, 8 % of the height) below the highest that have
//    higher columns on all four sides along their row and column (enclosed by a rim)
//  2 basin depth: their mean depth below the highest, / the object's height (0 without one)
//  3 raised spots: share of the upper columns (top in the upper 40 % of the height) at least one
//    voxel above the median of the footprint's columns in their 5x5 neighbourhood
//  4 sunken spots: share of the upper columns at least one voxel below that median
//  5 spot count: 4-connected groups of raised spots of 2 columns up to 5 % of the footprint
//  6 upper share: upper columns / footprint columns
// All zero for no voxels.
std::array<float, kTopReliefSize> topRelief(const std::vector<VoxelIndex>& voxels, int resolution);

}  // namespace sagrid
