// A folder that appears whole or not at all (an exported object, a corpus): files are written into
// a hidden sibling (".<name>.partial-<pid>-<n>") and the folder is renamed onto its final name at
// the end, so an error, a crash or kill -9 never leaves a half-written folder under its real name;
// the hidden leftovers of a killed run are removed by the next run for the same folder.
#pragma once

#include <filesystem>
#include <string>

namespace sagrid {

// Throws FileError when `target` exists and is not a folder, or is a non-empty folder without
// `marker` (the file an earlier run of the same kind leaves, e.g. corpus.json): a user's folder is
// never replaced.
void requireReplaceableFolder(const std::filesystem::path& target, const std::string& marker);

class StagedFolder {
 public:
  // Creates the staging folder beside `target` (creating target's parent as needed). Throws
  // FileError when it cannot.
  explicit StagedFolder(std::filesystem::path target);
  ~StagedFolder();  // removes the staging folder unless committed
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  const std::filesystem::path& path() const { return m_staging; }  // write here
  const std::filesystem::path& target() const { return m_target; }
  // Replaces `target` (an earlier run's folder) with the staged folder.
  void commit();

 private:
  std::filesystem::path m_target;
  std::filesystem::path m_staging;
  bool m_committed = false;
};

}  // namespace sagrid
