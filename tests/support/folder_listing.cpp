#include "support/folder_listing.h"

#include <system_error>

namespace sagrid::test {

std::set<std::filesystem::path> entriesBelow(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::set<fs::path> found;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    found.insert(it->path());
  return found;
}

}  // namespace sagrid::test
