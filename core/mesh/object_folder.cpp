#include "core/mesh/object_folder.h"

#include <system_error>

namespace sagrid {
namespace fs = std::filesystem;

fs::path objectFolderOf(const fs::path& meshPath) {
  const fs::path own = meshPath.parent_path().empty() ? fs::path(".") : meshPath.parent_path();
  fs::path folder = own;
  for (int level = 0; level < 3; ++level) {
    std::error_code ec;
    for (const char* marker : {"labels.json", "provenance.json", "model.config", "model.sdf"}) {
      if (fs::is_regular_file(folder / marker, ec)) return folder;
    }
    const fs::path parent = fs::absolute(folder, ec).lexically_normal().parent_path();
    if (ec || parent == fs::absolute(folder, ec).lexically_normal()) break;
    folder = parent;
  }
  return own;
}

}  // namespace sagrid
