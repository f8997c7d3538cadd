// Test-time augmentation over the symmetries the network was trained with (paper III-C: quarter
// turns about z and reflections across x/y — together the 8 symmetries of a square): the object's
// feature grid is turned/reflected exactly (voxel indices and vector channels such as normals),
// the model predicts each copy, and the fields, mapped back to the original voxels, are averaged.
// A model that has not quite learned the symmetry then votes 8 times instead of once.
#pragma once

#include <array>
#include <vector>

#include "core/features/feature_grid.h"

namespace sagrid {
namespace model {
class AffordanceModel;
}

struct GridSymmetry {
  int quarterTurns = 0;  // counter-clockwise about z through the grid centre
  bool flipX = false;    // x -> -x, after the turn
};

// The 8 symmetries; the first is the identity.
const std::array<GridSymmetry, 8>& gridSymmetries();

// Exact: a voxel maps onto a voxel of the same grid (the grid centre is a voxel corner).
VoxelIndex applySymmetry(const VoxelIndex& v, const GridSymmetry& s, int resolution);

// The grid turned/reflected, voxels in increasing linear order again; `order[n]` is the index in
// `grid.voxels` of the output's n-th voxel. Vector channels (triples of channel indices) are
// turned/reflected with the grid.
FeatureGrid transformFeatureGrid(const FeatureGrid& grid, const GridSymmetry& s,
                                 const std::vector<std::array<int, 3>>& vectorChannels,
                                 std::vector<std::size_t>* order = nullptr);

// Mean of the model's predicted distances over `symmetries` copies (the first `count` of
// gridSymmetries(), 1..8), in the order of grid.voxels.
std::vector<float> symmetryAveragedDistances(const model::AffordanceModel& model,
                                             const FeatureGrid& grid,
                                             const std::vector<std::array<int, 3>>& vectorChannels,
                                             int count = 8);

}  // namespace sagrid
