#include "core/common/resource_paths.h"

#include <system_error>

namespace sagrid {
namespace fs = std::filesystem;

fs::path executableDir() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

std::vector<fs::path> resourceRoots() {
  std::vector<fs::path> roots{"resources"};
  const fs::path binDir = executableDir();
  if (!binDir.empty()) roots.push_back((binDir / ".." / "share" / "sagrid").lexically_normal());
  roots.push_back(fs::path(SAGRID_SOURCE_DIR) / "resources");
  return roots;
}

fs::path findResourceDir(const std::string& relative, const std::vector<fs::path>& roots) {
  for (const auto& root : roots) {
    std::error_code ec;
    if (fs::is_directory(root / relative, ec)) return root / relative;
  }
  // Nothing found: name the installed location (the second root) when there is one.
  if (roots.size() > 1) return roots[1] / relative;
  return roots.empty() ? fs::path(relative) : roots.front() / relative;
}

fs::path resourceDir(const std::string& relative) {
  return findResourceDir(relative, resourceRoots());
}

fs::path defaultModelsDir() { return resourceDir("models"); }

}  // namespace sagrid
