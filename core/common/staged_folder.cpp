#include "core/common/staged_folder.h"

#include <unistd.h>

#include <system_error>

#include "core/common/error.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {
fs::path sibling(const fs::path& target, const std::string& kind) {
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  return parent / ("." + target.filename().string() + "." + kind + "-" + std::to_string(::getpid()));
}
}  // namespace

StagedFolder::StagedFolder(fs::path target, const std::string& marker) : m_target(std::move(target)) {
  if (m_target.empty()) throw InvalidArgument("an output folder is required");
  if (fs::exists(m_target)) {
    if (!fs::is_directory(m_target)) throw FileError(m_target, "exists and is not a folder");
    if (!fs::is_empty(m_target) && !fs::exists(m_target / marker)) {
      throw FileError(m_target, "is a non-empty folder that holds no " + marker +
                                    "; choose an empty or new folder");
    }
  }
  if (m_target.has_parent_path()) fs::create_directories(m_target.parent_path());
  m_staging = sibling(m_target, "tmp");
  fs::remove_all(m_staging);
  fs::create_directories(m_staging);
}

StagedFolder::~StagedFolder() {
  if (m_committed) return;
  std::error_code ec;
  fs::remove_all(m_staging, ec);
}

void StagedFolder::commit() {
  const fs::path old = sibling(m_target, "old");
  if (fs::exists(m_target)) fs::rename(m_target, old);
  fs::rename(m_staging, m_target);
  m_committed = true;
  std::error_code ec;
  fs::remove_all(old, ec);
}

}  // namespace sagrid
