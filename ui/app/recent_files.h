// The recently opened files and folders (most recent first, at most 10), kept in a small JSON
// file (by default ~/.config/sagrid/recent.json) so File -> Recent survives restarts.
#pragma once

#include <filesystem>
#include <vector>

namespace sagrid::ui {

class RecentFiles {
 public:
  explicit RecentFiles(std::filesystem::path storage = {});  // empty = in memory only
  static std::filesystem::path defaultStorage();
  void add(const std::filesystem::path& path);
  const std::vector<std::filesystem::path>& paths() const { return m_paths; }

 private:
  std::filesystem::path m_storage;
  std::vector<std::filesystem::path> m_paths;
};

}  // namespace sagrid::ui
