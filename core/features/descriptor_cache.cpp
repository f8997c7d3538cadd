#include "core/features/descriptor_cache.h"

#include <nlohmann/json.hpp>
#include <optional>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/sha256.h"
#include "core/features/feature_cache.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {
fs::path descriptorEntry(const fs::path& dir, const std::string& sha, const std::string& hash,
                         const std::string& variant) {
  return dir / (sha + "-" + hash + (variant.empty() ? "" : "-" + variant) + ".descriptor.json");
}

// The entry's content; one written before entries kept the top relief only when `needTopRelief`
// is false.
std::optional<ObjectDescriptor> loadDescriptor(const fs::path& entry, const std::string& sha,
                                               const std::string& hash, bool needTopRelief) {
  std::error_code ec;
  if (!fs::exists(entry, ec)) return std::nullopt;
  try {
    const auto j = nlohmann::json::parse(readFileBytes(entry));
    const bool hasRelief = j.contains("top_relief");
    if (j.at("mesh_sha256") == sha && j.at("config_hash") == hash &&
        (hasRelief || !needTopRelief)) {
      ObjectDescriptor d;
      d.descriptor = j.at("descriptor").get<std::vector<float>>();
      if (hasRelief) d.topRelief = j.at("top_relief").get<std::array<float, kTopReliefSize>>();
      return d;
    }
  } catch (const std::exception& e) {
    logger()->warn("descriptor cache: rewriting unusable entry {}: {}", entry.string(), e.what());
  }
  return std::nullopt;
}
}  // namespace

ObjectDescriptor extractObjectDescriptor(const fs::path& meshFile, const FeatureOptions& options,
                                         DescriptorSource* source, bool needTopRelief) {
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
    if (auto cached = loadDescriptor(entry, sha, hash, needTopRelief)) {
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
  if (from == DescriptorSource::Computed) {
    if (!mesh) mesh = importMesh(meshFile, ImportOptions(framed.up));
    take(computeFeatures(*mesh, framed));
  }
  if (!entry.empty()) {
    std::error_code ec;
    fs::create_directories(options.cacheDir, ec);
    if (ec)
      throw FileError(options.cacheDir, "cannot create the feature cache folder: " + ec.message());
    writeFileAtomic(entry, nlohmann::json{{"mesh_sha256", sha},
                                          {"config_hash", hash},
                                          {"descriptor", d.descriptor},
                                          {"top_relief", d.topRelief}}
                                   .dump() +
                               "\n");
  }
  if (source) *source = from;
  return d;
}

std::vector<float> extractDescriptor(const fs::path& meshFile, const FeatureOptions& options,
                                     DescriptorSource* source) {
  return extractObjectDescriptor(meshFile, options, source, /*needTopRelief=*/false).descriptor;
}

}  // namespace sagrid
