#include "core/features/feature_npz.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/common/value_ranges.h"
#include "core/io/json_file.h"
#include "core/io/npz.h"

namespace sagrid {

namespace {
template <typename T>
void appendBytes(std::string& out, const std::vector<T>& v) {
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

std::vector<std::int32_t> coordsOf(const FeatureGrid& grid) {
  std::vector<std::int32_t> coords;
  coords.reserve(grid.voxels.size() * 3);
  for (const VoxelIndex& v : grid.voxels) {
    coords.push_back(v.i);
    coords.push_back(v.j);
    coords.push_back(v.k);
  }
  return coords;
}

const NpyArray& entry(const NpzArchive& npz, const std::string& key, const char* dtype,
                      const std::filesystem::path& path) {
  const auto it = npz.find(key);
  if (it == npz.end()) throw FileError(path, "feature file has no '" + key + "' array");
  if (it->second.dtype != dtype) {
    throw FileError(path, "'" + key + "' has dtype " + it->second.dtype + ", expected " + dtype);
  }
  return it->second;
}
}  // namespace

std::string featureChecksum(const FeatureGrid& grid) {
  std::string bytes;
  appendBytes(bytes, coordsOf(grid));
  appendBytes(bytes, grid.values);
  appendBytes(bytes, grid.descriptor);
  appendBytes(bytes,
              std::vector<float>{grid.normalization.center.x(), grid.normalization.center.y(),
                                 grid.normalization.center.z(), grid.normalization.scale});
  return sha256Hex(bytes);
}

void writeFeatureNpz(const std::filesystem::path& path, const FeatureGrid& grid,
                     const nlohmann::json& extra) {
  if (grid.values.size() != grid.voxels.size() * static_cast<std::size_t>(grid.channels)) {
    throw Error("feature grid has " + std::to_string(grid.values.size()) + " values for " +
                std::to_string(grid.voxels.size()) + " voxels x " + std::to_string(grid.channels) +
                " channels");
  }
  nlohmann::json meta = extra.is_object() ? extra : nlohmann::json::object();
  meta["schema"] = kFeatureNpzSchema;
  meta["backend"] = grid.backend;
  meta["config_hash"] = grid.configHash;
  meta["resolution"] = grid.resolution;
  meta["channels"] = grid.channels;
  meta["checksum"] = featureChecksum(grid);
  // Paths from non-UTF-8 file names must not make the write throw (bytes become U+FFFD).
  const std::string metaText = meta.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  NpzArchive npz;
  npz["coords"] = NpyArray::from(coordsOf(grid), {grid.voxels.size(), 3});
  npz["feats"] =
      NpyArray::from(grid.values, {grid.voxels.size(), static_cast<std::size_t>(grid.channels)});
  npz["descriptor"] = NpyArray::from(grid.descriptor);
  npz["normalization_center"] = NpyArray::from(std::vector<float>{
      grid.normalization.center.x(), grid.normalization.center.y(), grid.normalization.center.z()});
  npz["normalization_scale"] = NpyArray::from(std::vector<float>{grid.normalization.scale}, {});
  npz["metadata"] = NpyArray::from(std::vector<std::uint8_t>(metaText.begin(), metaText.end()));
  writeNpz(path, npz);
}

FeatureGrid readFeatureNpz(const std::filesystem::path& path, nlohmann::json* metadata) {
  const NpzArchive npz = readNpz(path);
  const NpyArray& metaArray = entry(npz, "metadata", "uint8", path);
  nlohmann::json meta;
  meta = parseJsonDocument(
      std::string_view(reinterpret_cast<const char*>(metaArray.data.data()), metaArray.data.size()),
      path.string() + " (metadata entry)");
  FeatureGrid grid;
  try {
    grid.backend = meta.at("backend").get<std::string>();
    grid.configHash = meta.at("config_hash").get<std::string>();
    grid.resolution = meta.at("resolution").get<int>();
    grid.channels = meta.at("channels").get<int>();
  } catch (const nlohmann::json::exception& e) {
    throw FileError(path, std::string("metadata is incomplete: ") + e.what());
  }
  if (grid.resolution < 1 || grid.resolution > 1024 || grid.channels < 1 || grid.channels > 4096)
    throw FileError(path, "metadata resolution or channel count is out of range");
  const NpyArray& coords = entry(npz, "coords", "int32", path);
  const NpyArray& feats = entry(npz, "feats", "float32", path);
  if (coords.shape.size() != 2 || coords.shape[1] != 3)
    throw FileError(path, "'coords' must be N x 3");
  const std::size_t n = coords.shape[0];
  if (feats.shape.size() != 2 || feats.shape[0] != n ||
      feats.shape[1] != static_cast<std::size_t>(grid.channels)) {
    throw FileError(path,
                    "'feats' must be " + std::to_string(n) + " x " + std::to_string(grid.channels));
  }
  const std::vector<std::int32_t> c = coords.as<std::int32_t>();
  for (std::size_t v = 0; v < n; ++v) {
    const VoxelIndex idx{c[v * 3], c[v * 3 + 1], c[v * 3 + 2]};
    if (std::min({idx.i, idx.j, idx.k}) < 0 || std::max({idx.i, idx.j, idx.k}) >= grid.resolution) {
      throw FileError(
          path, "voxel coordinate outside the " + std::to_string(grid.resolution) + "^3 grid");
    }
    grid.voxels.push_back(idx);
  }
  grid.values = feats.as<float>();
  grid.descriptor = entry(npz, "descriptor", "float32", path).as<float>();
  const std::vector<float> centre = entry(npz, "normalization_center", "float32", path).as<float>();
  const std::vector<float> scale = entry(npz, "normalization_scale", "float32", path).as<float>();
  if (centre.size() != 3 || scale.size() != 1)
    throw FileError(path, "normalization arrays have wrong sizes");
  grid.normalization.center = Eigen::Vector3f(centre[0], centre[1], centre[2]);
  grid.normalization.scale = scale[0];
  // A recomputed checksum does not make the numbers usable: scale 0 or NaN gave points of
  // [null, null, null].
  if (!(std::isfinite(grid.normalization.scale) && grid.normalization.scale > 0))
    throw FileError(path, "normalization scale is " + std::to_string(grid.normalization.scale) +
                              "; it must be a positive finite number");
  if (!grid.normalization.center.allFinite() ||
      grid.normalization.center.cwiseAbs().maxCoeff() > kMaxCoordinate)
    throw FileError(path, "normalization centre is not finite or beyond 1e9");
  auto allFinite = [](const std::vector<float>& v) {
    return std::all_of(v.begin(), v.end(), [](float x) { return std::isfinite(x); });
  };
  if (!allFinite(grid.values) || !allFinite(grid.descriptor))
    throw FileError(path, "features hold values that are not finite");
  if (meta.value("checksum", std::string()) != featureChecksum(grid)) {
    throw FileError(path, "checksum mismatch: the feature file is damaged");
  }
  if (metadata) *metadata = std::move(meta);
  return grid;
}

}  // namespace sagrid
