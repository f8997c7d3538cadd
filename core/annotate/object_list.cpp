#include "core/annotate/object_list.h"

#include <set>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace sagrid {
namespace fs = std::filesystem;

bool isObjectListFile(const fs::path& path) {
  const auto ext = path.extension().string();
  return ext == ".txt" || ext == ".list";
}

std::vector<MeshFile> readObjectList(const fs::path& listFile) {
  std::istringstream in(readFileBytes(listFile));
  const fs::path base = listFile.parent_path();
  std::vector<MeshFile> files;
  std::set<std::string> ids;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    MeshFile f;
    f.path = tab == std::string::npos ? line : line.substr(tab + 1);
    f.id = tab == std::string::npos ? objectIdOfFile(f.path) : line.substr(0, tab);
    const std::string where = "line " + std::to_string(number) + ": ";
    if (f.path.empty() || f.id.empty())
      throw FileError(listFile, where + "expected <id><TAB><mesh path> or a mesh path");
    // The id names the output folder OUT/<id>: it must stay a single folder name.
    if (f.id.find_first_of("/\\") != std::string::npos || f.id == "." || f.id == "..")
      throw FileError(listFile, where + "object id '" + f.id +
                                    "' is not a folder name (no / or \\, not . or ..)");
    if (!ids.insert(f.id).second)
      throw FileError(listFile, where + "object id '" + f.id +
                                    "' is listed twice (give each line its own id: "
                                    "<id><TAB><mesh path>)");
    if (f.path.is_relative()) f.path = base / f.path;
    files.push_back(std::move(f));
  }
  return files;
}

void writeObjectList(const fs::path& listFile, const std::vector<MeshFile>& files) {
  std::string text = "# sagrid object list: <id><TAB><mesh path>\n";
  for (const auto& f : files)
    text += f.id + "\t" + fs::absolute(f.path).lexically_normal().string() + "\n";
  writeFileAtomic(listFile, text);
}

std::vector<MeshFile> listObjects(const fs::path& input) {
  std::error_code ec;
  if (isObjectListFile(input) && !fs::is_directory(input, ec)) return readObjectList(input);
  return findMeshFiles(input);
}

}  // namespace sagrid
