#include "core/grid/voxel_export.h"

#include <cstdio>

#include "core/common/ascii_case.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/io/npz.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

void writeNpzVoxels(const fs::path& path, const VoxelGrid& grid, const Normalization& n) {
  const auto voxels = grid.occupiedVoxels();
  NpzArchive archive;
  if (grid.resolution() <= 256) {
    std::vector<std::uint8_t> coords;
    coords.reserve(voxels.size() * 3);
    for (const auto& v : voxels) {
      coords.insert(coords.end(), {static_cast<std::uint8_t>(v.i), static_cast<std::uint8_t>(v.j),
                                   static_cast<std::uint8_t>(v.k)});
    }
    archive["coords"] = NpyArray::from(coords, {voxels.size(), 3});
  } else {
    std::vector<std::int32_t> coords;
    coords.reserve(voxels.size() * 3);
    for (const auto& v : voxels) coords.insert(coords.end(), {v.i, v.j, v.k});
    archive["coords"] = NpyArray::from(coords, {voxels.size(), 3});
  }
  archive["resolution"] = NpyArray::from(std::vector<std::int64_t>{grid.resolution()}, {});
  archive["center"] = NpyArray::from(std::vector<float>{n.center.x(), n.center.y(), n.center.z()});
  archive["scale"] = NpyArray::from(std::vector<float>{n.scale}, {});
  writeNpz(path, archive);
}

void writePlyVoxels(const fs::path& path, const VoxelGrid& grid) {
  const auto voxels = grid.occupiedVoxels();
  std::string text = "ply\nformat ascii 1.0\ncomment sagrid voxel centres, normalized frame, grid " +
                     std::to_string(grid.resolution()) + "^3\nelement vertex " +
                     std::to_string(voxels.size()) + "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  char line[96];
  for (const auto& v : voxels) {
    const Eigen::Vector3f c = voxelCenter(v, grid.resolution());
    std::snprintf(line, sizeof(line), "%.9g %.9g %.9g\n", c.x(), c.y(), c.z());
    text += line;
  }
  writeFileAtomic(path, text);
}
}  // namespace

void checkVoxelOutputPath(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".npz" && ext != ".ply") {
    throw FileError(path, "unsupported output format '" + ext + "' (use .npz or .ply)");
  }
  if (path.has_parent_path() && !fs::is_directory(path.parent_path())) {
    throw FileError(path, "the folder " + path.parent_path().string() + " does not exist");
  }
}

void writeVoxels(const fs::path& path, const VoxelGrid& grid, const Normalization& normalization) {
  checkVoxelOutputPath(path);
  if (lowerExtension(path) == ".npz")
    writeNpzVoxels(path, grid, normalization);
  else writePlyVoxels(path, grid);
}

}  // namespace sagrid
