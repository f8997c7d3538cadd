#include "ui/app/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/log.h"

namespace sagrid::ui {

namespace fs = std::filesystem;
constexpr std::size_t kMaxRecent = 10;

RecentFiles::RecentFiles(fs::path storage) : m_storage(std::move(storage)) {
  std::error_code ec;
  if (m_storage.empty() || !fs::exists(m_storage, ec)) return;
  try {
    for (const auto& p :
         nlohmann::json::parse(readFileBytes(m_storage)).value("recent", nlohmann::json::array())) {
      m_paths.emplace_back(p.get<std::string>());
    }
  } catch (const std::exception& e) {
    logger()->warn("{}: ignoring unreadable recent-files list ({})", m_storage.string(), e.what());
  }
}

fs::path RecentFiles::defaultStorage() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config)
    return fs::path(config) / "sagrid" / "recent.json";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".config" / "sagrid" / "recent.json";
  return {};
}

void RecentFiles::add(const fs::path& path) {
  const fs::path absolute = fs::absolute(path).lexically_normal();
  m_paths.erase(std::remove(m_paths.begin(), m_paths.end(), absolute), m_paths.end());
  m_paths.insert(m_paths.begin(), absolute);
  if (m_paths.size() > kMaxRecent) m_paths.resize(kMaxRecent);
  if (m_storage.empty()) return;
  nlohmann::json list = nlohmann::json::array();
  for (const auto& p : m_paths) list.push_back(p.string());
  try {
    std::error_code ec;
    fs::create_directories(m_storage.parent_path(), ec);
    writeFileAtomic(m_storage, nlohmann::json{{"recent", list}}.dump(2) + "\n");
  } catch (const Error& e) {
    logger()->warn("cannot remember recent files: {}", e.what());  // not worth a modal
  }
}

}  // namespace sagrid::ui
