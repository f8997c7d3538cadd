#include "core/features/descriptor_cache.h"

#include <nlohmann/json.hpp>
#include <optional>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/sha256.h"
#include "core/features/feature_cache.h"
#include "core/geometry/part_statistics.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {
fs::path descriptorEntry(const fs::path& dir, const std::string& sha, const std::string& hash,
                         const std::string& variant) {
  return dir / (sha + "-" + hash + (variant.empty() ? "" : "-" + variant) + ".descriptor.json");
}

// The entry's content; one written without the top relief (before entries kept it) or without
// the part statistics only where they are not needed.
std::optional<ObjectDescriptor> loadDescriptor(const fs::path& entry, const std::string& sha,
                                               const std::string& hash, bool needTopRelief,
                                               bool needPartStatistics) {
  std::error_code ec;
  if (!fs::exists(entry, ec)) return std::nullopt;
  try {
    const auto j = nlohmann::json::parse(readFileBytes(entry));
    const bool hasRelief = j.contains("top_relief"), hasParts = j.contains("part_statistics");
    if (j.at("mesh_sha256") == sha && j.at("config_hash") == hash &&
        (hasRelief || !needTopRelief) && (hasParts || !needPartStatistics)) {
      ObjectDescriptor d;
      d.descriptor = j.at("descriptor").get<std::vector<float>>();
      if (hasRelief) d.topRelief = j.at("top_relief").get<std::array<float, kTopReliefSize>>();
      if (hasParts) {
        d.partStatistics = j.at("part_statistics").get<std::array<float, kPartStatisticsSize>>();
        d.hasPartStatistics = true;
      }
      return d;
    }
  } catch (const std::exception& e) {
    logger()->warn("descriptor cache: rewriting unusable entry {}: {}", entry.string(), e.what());
  }
  return std::nullopt;
}
}  // namespace

ObjectDescriptor extractObjectDescriptor(const fs::path& meshFile, const FeatureOptions& options,
                                         DescriptorSource* source, bool needTopRelief,
                                         bool needPartStatistics) {
  const std::string hash = featureConfigHash(options);  // validates the backend
  // Without an up axis it is detected from the geometry, as `annotate` does: the descriptor
  // entry is then keyed "updetected" (the detection is a function of the file's bytes), so a
  // cached entry needs no import.
  const std::string variant = options.up ? std::string("up") + toString(*options.up) : "updetected";
  std::string sha;
  fs::path entry;
  if (!options.cacheDir.empty()) {
    sha = sha256Hex(readFileBytes(meshFile));
    entry = descriptorEntry(options.cacheDir, sha, hash, variant);
    if (auto cached = loadDescriptor(entry, sha, hash, needTopRelief, needPartStatistics)) {
      if (source) *source = DescriptorSource::DescriptorCache;
      return std::move(*cached);
    }
  }
  ObjectDescriptor d;
  DescriptorSource from = DescriptorSource::Computed;
  auto take = [&d](const FeatureGrid& grid) {
    d.descriptor = grid.descriptor;
    d.topRelief = topRelief(grid.voxels, grid.resolution);
  };
  // The full feature entries are keyed by the axis used (annotate keys them by the detected one).
  std::optional<Mesh> mesh;
  FeatureOptions framed = options;
  if (!framed.up) {
    mesh = importMesh(meshFile, ImportOptions(std::nullopt, /*detect=*/true));
    framed.up = mesh->fileUp;
  }
  if (!options.cacheDir.empty()) {
    if (auto grid = FeatureCache(options.cacheDir)
                        .load(sha, hash, std::string("up") + toString(*framed.up))) {
      take(*grid);
      from = DescriptorSource::FeatureCache;
    }
  }
  if (from == DescriptorSource::Computed || needPartStatistics) {
    if (!mesh) mesh = importMesh(meshFile, ImportOptions(framed.up));
    if (from == DescriptorSource::Computed) take(computeFeatures(*mesh, framed));
  }
  // Whenever the mesh was read anyway (its parts cost little beside its features).
  if (mesh) {
    d.partStatistics = partStatistics(*mesh);
    d.hasPartStatistics = true;
  }
  if (!entry.empty()) {
    std::error_code ec;
    fs::create_directories(options.cacheDir, ec);
    if (ec)
      throw FileError(options.cacheDir, "cannot create the feature cache folder: " + ec.message());
    nlohmann::json j{{"mesh_sha256", sha},
                     {"config_hash", hash},
                     {"descriptor", d.descriptor},
                     {"top_relief", d.topRelief}};
    if (d.hasPartStatistics) j["part_statistics"] = d.partStatistics;
    writeFileAtomic(entry, j.dump() + "\n");
  }
  if (source) *source = from;
  return d;
}

std::vector<float> extractDescriptor(const fs::path& meshFile, const FeatureOptions& options,
                                     DescriptorSource* source) {
  return extractObjectDescriptor(meshFile, options, source, /*needTopRelief=*/false,
                                 /*needPartStatistics=*/false)
      .descriptor;
}

}  // namespace sagrid
