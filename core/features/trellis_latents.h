// Import of TRELLIS SLAT latents as TRELLIS's own toolkit writes them
// (dataset_toolkits/encode_latent.py: latents/<model>/<sha256>.npz with "coords" uint8 N x 3
// voxel indices of the 64^3 grid and "feats" float32 N x 8).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/grid/voxel_grid.h"

namespace sagrid {

struct TrellisLatents {
  int channels = 0;
  std::vector<VoxelIndex> voxels;  // sorted by linear index, unique
  std::vector<float> feats;        // voxels.size() x channels, in the order of `voxels`
};

// Validates dtypes (coords uint8 or any integer type holding 0..N-1, feats float32), shapes
// (N x 3, N x C with the same N) and the grid size: all coordinates below `resolution`, and a
// latent file of another grid size (e.g. 32^3, recognised by its coordinate range) is refused.
// Throws FileError naming the file and the problem.
TrellisLatents readTrellisLatents(const std::filesystem::path& npzFile,
                                  int resolution = kDefaultGridResolution);

// `fileOrDir` is the .npz itself or a folder holding <sha256>.npz (TRELLIS's naming).
std::filesystem::path trellisLatentFile(const std::filesystem::path& fileOrDir,
                                        const std::string& meshSha256);

}  // namespace sagrid
