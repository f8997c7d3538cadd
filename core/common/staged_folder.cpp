#include "core/common/staged_folder.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <string>
#include <system_error>

#include "core/common/error.h"

namespace sagrid {

namespace fs = std::filesystem;

namespace {
fs::path hiddenSibling(const fs::path& target, const char* kind) {
  static std::atomic<unsigned> counter{0};
  return target.parent_path() / ("." + target.filename().string() + "." + kind + "-" +
                                 std::to_string(::getpid()) + "-" + std::to_string(counter++));
}
// Removes staging and replaced folders of `target` left by runs that were killed (their process
// is gone), so a rerun leaves no debris. Folders of runs still alive are left alone.
void removeStaleSiblings(const fs::path& target) {
  std::error_code ec;
  const std::string name = "." + target.filename().string() + ".";
  for (const auto& item : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string entry = item.path().filename().string();
    if (entry.rfind(name, 0) != 0) continue;
    const std::string rest = entry.substr(name.size());  // partial-<pid>-<n> or previous-<pid>-<n>
    const std::size_t dash = rest.find('-');
    if (dash == std::string::npos ||
        (rest.compare(0, dash, "partial") != 0 && rest.compare(0, dash, "previous") != 0))
      continue;
    const long pid = std::strtol(rest.c_str() + dash + 1, nullptr, 10);
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH) {
      std::error_code ignored;
      fs::remove_all(item.path(), ignored);
    }
  }
}

}  // namespace

void requireReplaceableFolder(const fs::path& target, const std::string& marker) {
  if (!fs::exists(target)) return;
  if (!fs::is_directory(target)) throw FileError(target, "exists and is not a folder");
  if (!fs::is_empty(target) && !fs::exists(target / marker)) {
    throw FileError(target, "is a non-empty folder that holds no " + marker + "; choose an empty or new folder");
  }
}

StagedFolder::StagedFolder(fs::path target)
    : m_target(std::move(target)), m_staging(hiddenSibling(m_target, "partial")) {
  std::error_code ec;
  if (!m_target.parent_path().empty()) fs::create_directories(m_target.parent_path(), ec);
  if (fs::is_directory(m_target.parent_path(), ec)) removeStaleSiblings(m_target);
  fs::create_directories(m_staging, ec);
  if (ec) throw FileError(m_target.parent_path(), "cannot create a folder here: " + ec.message());
}

StagedFolder::~StagedFolder() {
  if (m_committed) return;
  std::error_code ignored;
  fs::remove_all(m_staging, ignored);  // best effort: the target was never touched
}

void StagedFolder::commit() {
  std::error_code ec;
  fs::path previous;
  if (fs::exists(fs::symlink_status(m_target, ec))) {
    previous = hiddenSibling(m_target, "previous");
    fs::rename(m_target, previous, ec);
    if (ec) throw FileError(m_target, "cannot replace the earlier folder: " + ec.message());
  }
  fs::rename(m_staging, m_target, ec);
  if (ec) {
    std::error_code ignored;
    if (!previous.empty()) fs::rename(previous, m_target, ignored);
    throw FileError(m_target, "cannot move the finished folder into place: " + ec.message());
  }
  m_committed = true;
  if (!previous.empty()) fs::remove_all(previous, ec);  // a leftover is hidden and harmless
}

}  // namespace sagrid
