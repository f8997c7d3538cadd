#include "core/features/descriptor_cache.h"

#include <nlohmann/json.hpp>

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

std::optional<std::vector<float>> loadDescriptor(const fs::path& entry, const std::string& sha,
                                                 const std::string& hash) {
  std::error_code ec;
  if (!fs::exists(entry, ec)) return std::nullopt;
  try {
    const auto j = nlohmann::json::parse(readFileBytes(entry));
    if (j.at("mesh_sha256") == sha && j.at("config_hash") == hash)
      return j.at("descriptor").get<std::vector<float>>();
  } catch (const std::exception& e) {
    logger()->warn("descriptor cache: rewriting unusable entry {}: {}", entry.string(), e.what());
  }
  return std::nullopt;
}
}  // namespace

std::vector<float> extractDescriptor(const fs::path& meshFile, const FeatureOptions& options,
                                     DescriptorSource* source) {
  const std::string hash = featureConfigHash(options);  // validates the backend
  const std::string variant = options.up ? std::string("up") + toString(*options.up) : "";
  std::string sha;
  fs::path entry;
  if (!options.cacheDir.empty()) {
    sha = sha256Hex(readFileBytes(meshFile));
    entry = descriptorEntry(options.cacheDir, sha, hash, variant);
    if (auto d = loadDescriptor(entry, sha, hash)) {
      if (source) *source = DescriptorSource::DescriptorCache;
      return std::move(*d);
    }
  }
  std::vector<float> descriptor;
  DescriptorSource from = DescriptorSource::Computed;
  if (!options.cacheDir.empty()) {
    if (auto grid = FeatureCache(options.cacheDir).load(sha, hash, variant)) {
      descriptor = std::move(grid->descriptor);
      from = DescriptorSource::FeatureCache;
    }
  }
  if (from == DescriptorSource::Computed) {
    const Mesh mesh = importMesh(meshFile, ImportOptions(options.up));
    descriptor = computeFeatures(mesh, options).descriptor;
  }
  if (!entry.empty()) {
    std::error_code ec;
    fs::create_directories(options.cacheDir, ec);
    if (ec)
      throw FileError(options.cacheDir, "cannot create the feature cache folder: " + ec.message());
    writeFileAtomic(
        entry,
        nlohmann::json{{"mesh_sha256", sha}, {"config_hash", hash}, {"descriptor", descriptor}}
                .dump() +
            "\n");
  }
  if (source) *source = from;
  return descriptor;
}

}  // namespace sagrid
