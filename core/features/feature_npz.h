// FeatureGrid <-> NumPy .npz, the interchange format with Python tools and the on-disk cache
// format. Keys (numpy.load(path)[key]):
//   coords               int32   N x 3   voxel indices (i, j, k) of the occupied voxels
//   feats                float32 N x C   per-voxel features
//   descriptor           float32 D       object descriptor
//   normalization_center float32 3       mesh-frame bbox centre
//   normalization_scale  float32 ()      1 / largest extent; normalized = (p - center) * scale
//   metadata             uint8   bytes   UTF-8 JSON: json.loads(bytes(npz["metadata"]))
// metadata holds schema, backend, config_hash, resolution, channels, channel_names and a sha256
// checksum of the arrays, so a damaged file is detected, plus any extra fields given.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/features/feature_grid.h"

namespace sagrid {

constexpr const char* kFeatureNpzSchema = "sagrid.features/1";

// Atomic write. `extra` fields are merged into metadata (e.g. mesh path and sha256).
void writeFeatureNpz(const std::filesystem::path& path, const FeatureGrid& grid,
                     const nlohmann::json& extra = nlohmann::json::object());

// Throws FileError naming the file for unreadable files, missing keys, wrong dtypes or shapes,
// out-of-grid coordinates and checksum mismatches. `metadata` receives the parsed metadata.
FeatureGrid readFeatureNpz(const std::filesystem::path& path, nlohmann::json* metadata = nullptr);

// sha256 over coords, values, descriptor and normalization (what the checksum field holds).
std::string featureChecksum(const FeatureGrid& grid);

}  // namespace sagrid
