// On-disk cache of extracted features: one .npz per (mesh file sha256, feature-config hash,
// up-axis override) in a folder. A changed configuration gives a different key, so stale entries
// are never read; an entry that fails to load or whose checksum or key fields do not match is
// deleted and rebuilt, never trusted.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/features/feature_grid.h"

namespace sagrid {

class FeatureCache {
 public:
  explicit FeatureCache(std::filesystem::path dir) : m_dir(std::move(dir)) {}

  // `variant` distinguishes extractions of the same file and config that still differ (the
  // up-axis override); empty for none.
  std::filesystem::path entryPath(const std::string& meshSha256, const std::string& configHash,
                                  const std::string& variant = "") const;

  // The cached grid, or nullopt when absent or unusable (then the bad entry is removed).
  std::optional<FeatureGrid> load(const std::string& meshSha256, const std::string& configHash,
                                  const std::string& variant = "") const;
  // Atomic; creates the folder.
  void store(const std::string& meshSha256, const std::string& configHash, const FeatureGrid& grid,
             const std::string& variant = "") const;

 private:
  std::filesystem::path m_dir;
};

}  // namespace sagrid
