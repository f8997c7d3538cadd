// An output folder written whole or not at all (corpus builds): the work goes into a hidden
// sibling of the target, and commit() swaps it into place, removing the old folder only once the
// new one is complete. Destroyed without commit, the staging folder is removed and the target is
// left as it was.
#pragma once

#include <filesystem>
#include <string>

namespace sagrid {

class StagedFolder {
 public:
  // Throws FileError when `target` exists and is not a folder, or is a non-empty folder without
  // `marker` (the file an earlier build of the same kind leaves, e.g. corpus.json): a user's
  // folder is never replaced.
  StagedFolder(std::filesystem::path target, const std::string& marker);
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  // Where to write until commit().
  const std::filesystem::path& path() const { return m_staging; }
  void commit();

 private:
  std::filesystem::path m_target;
  std::filesystem::path m_staging;
  bool m_committed = false;
};

}  // namespace sagrid
