// Writing occupied voxels for other tools: NumPy .npz ("coords": N x 3 voxel indices, uint8 when
// the grid fits, else int32; "resolution"; the normalization as "center" and "scale") or a PLY
// point cloud of voxel centres in the normalized frame. Files are written atomically.
#pragma once

#include <filesystem>

#include "core/grid/normalization.h"
#include "core/grid/voxel_grid.h"

namespace sagrid {

// Throws FileError naming `path` when its extension is neither .npz nor .ply; call it before
// slow work so a bad --out fails at once.
void checkVoxelOutputPath(const std::filesystem::path& path);

void writeVoxels(const std::filesystem::path& path, const VoxelGrid& grid, const Normalization& normalization);

}  // namespace sagrid
