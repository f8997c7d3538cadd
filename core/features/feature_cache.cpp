#include "core/features/feature_cache.h"

#include "core/common/error.h"
#include "core/common/log.h"
#include "core/features/feature_npz.h"

namespace sagrid {

std::filesystem::path FeatureCache::entryPath(const std::string& sha, const std::string& hash,
                                              const std::string& variant) const {
  return m_dir / (sha + "-" + hash + (variant.empty() ? "" : "-" + variant) + ".npz");
}

std::optional<FeatureGrid> FeatureCache::load(const std::string& sha, const std::string& hash,
                                              const std::string& variant) const {
  const auto path = entryPath(sha, hash, variant);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  std::string problem;
  try {
    nlohmann::json meta;
    FeatureGrid grid = readFeatureNpz(path, &meta);
    if (meta.value("mesh_sha256", std::string()) == sha && grid.configHash == hash) return grid;
    problem = "its key fields do not match its name";
  } catch (const Error& e) {
    problem = e.what();
  }
  logger()->warn("feature cache: rebuilding unusable entry {}: {}", path.string(), problem);
  std::filesystem::remove(path, ec);
  return std::nullopt;
}

void FeatureCache::store(const std::string& sha, const std::string& hash, const FeatureGrid& grid,
                         const std::string& variant) const {
  std::error_code ec;
  std::filesystem::create_directories(m_dir, ec);
  if (ec) throw FileError(m_dir, "cannot create the feature cache folder: " + ec.message());
  writeFeatureNpz(entryPath(sha, hash, variant), grid, {{"mesh_sha256", sha}});
}

}  // namespace sagrid
