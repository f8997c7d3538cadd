#include "core/mesh/object_folder.h"

#include <system_error>

namespace sagrid {
namespace fs = std::filesystem;

fs::path objectFolderOf(const fs::path& meshPath) {
  const fs::path own = meshPath.parent_path().empty() ? fs::path(".") : meshPath.parent_path();
  std::error_code ec;
  fs::path folder = fs::absolute(own, ec).lexically_normal();
  if (ec) return own;
  for (int level = 0; level < 3; ++level) {
    for (const char* marker : {"labels.json", "provenance.json", "model.config", "model.sdf"}) {
      if (fs::is_regular_file(folder / marker, ec)) return level == 0 ? own : folder;
    }
    if (folder == folder.parent_path()) break;  // the root
    folder = folder.parent_path();
  }
  return own;
}

}  // namespace sagrid
