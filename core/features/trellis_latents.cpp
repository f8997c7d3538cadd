#include "core/features/trellis_latents.h"

#include <algorithm>

#include "core/common/error.h"
#include "core/io/npz.h"

namespace sagrid {

TrellisLatents readTrellisLatents(const std::filesystem::path& path, int resolution) {
  const NpzArchive npz = readNpz(path);
  const auto coordsIt = npz.find("coords"), featsIt = npz.find("feats");
  if (coordsIt == npz.end() || featsIt == npz.end()) {
    throw FileError(path,
                    "not a TRELLIS latent file: needs 'coords' (uint8 N x 3) and 'feats' "
                    "(float32 N x 8)");
  }
  const NpyArray& coords = coordsIt->second;
  const NpyArray& feats = featsIt->second;
  if (coords.dtype != "uint8" && coords.dtype != "int32" && coords.dtype != "int64") {
    throw FileError(path, "'coords' has dtype " + coords.dtype +
                              "; TRELLIS writes uint8 voxel indices (integers expected)");
  }
  if (feats.dtype != "float32") {
    throw FileError(path, "'feats' has dtype " + feats.dtype + "; TRELLIS writes float32");
  }
  if (coords.shape.size() != 2 || coords.shape[1] != 3) {
    throw FileError(path, "'coords' must be N x 3");
  }
  const std::size_t n = coords.shape[0];
  if (n == 0) throw FileError(path, "no voxels in the latent file");
  if (feats.shape.size() != 2 || feats.shape[0] != n) {
    throw FileError(path, "'feats' must be " + std::to_string(n) + " x C (one row per voxel)");
  }
  const std::vector<double> c = coords.asDouble();
  const double lo = *std::min_element(c.begin(), c.end());
  const double hi = *std::max_element(c.begin(), c.end());
  if (lo < 0 || hi >= resolution) {
    throw FileError(path, "voxel coordinates span " + std::to_string(static_cast<long>(lo)) + ".." +
                              std::to_string(static_cast<long>(hi)) + ", outside the " +
                              std::to_string(resolution) + "^3 grid");
  }
  // A normalized object touches both ends of its largest axis, so on a 64^3 grid some
  // coordinate reaches the upper half; coordinates all below 32 mean a 32^3 (or coarser) grid.
  if (hi < resolution / 2) {
    throw FileError(path, "voxel coordinates only span 0.." +
                              std::to_string(static_cast<long>(hi)) + ": this is a " +
                              std::to_string(static_cast<long>(hi) + 1) +
                              "^3-sized grid, but TRELLIS SLAT latents must be on the " +
                              std::to_string(resolution) + "^3 grid");
  }
  TrellisLatents out;
  out.channels = static_cast<int>(feats.shape[1]);
  const std::vector<float> f = feats.as<float>();
  std::vector<std::pair<VoxelIndex, std::size_t>> order;
  order.reserve(n);
  for (std::size_t v = 0; v < n; ++v) {
    order.push_back({VoxelIndex{static_cast<int>(c[v * 3]), static_cast<int>(c[v * 3 + 1]),
                                static_cast<int>(c[v * 3 + 2])},
                     v});
  }
  std::sort(order.begin(), order.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t v = 1; v < n; ++v) {
    if (order[v].first == order[v - 1].first) {
      throw FileError(path, "voxel (" + std::to_string(order[v].first.i) + ", " +
                                std::to_string(order[v].first.j) + ", " +
                                std::to_string(order[v].first.k) + ") appears twice");
    }
  }
  out.voxels.reserve(n);
  out.feats.reserve(f.size());
  for (const auto& [voxel, row] : order) {
    out.voxels.push_back(voxel);
    out.feats.insert(out.feats.end(), f.begin() + row * out.channels,
                     f.begin() + (row + 1) * out.channels);
  }
  return out;
}

std::filesystem::path trellisLatentFile(const std::filesystem::path& fileOrDir,
                                        const std::string& meshSha256) {
  std::error_code ec;
  if (std::filesystem::is_directory(fileOrDir, ec)) {
    const auto file = fileOrDir / (meshSha256 + ".npz");
    if (!std::filesystem::exists(file, ec)) {
      throw FileError(file,
                      "no TRELLIS latent for this mesh (TRELLIS names them <sha256 of the "
                      "mesh file>.npz)");
    }
    return file;
  }
  return fileOrDir;
}

}  // namespace sagrid
