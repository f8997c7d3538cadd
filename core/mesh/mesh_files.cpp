#include "core/mesh/mesh_files.h"

#include <algorithm>
#include <set>

#include "core/common/ascii_case.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/common/utf8.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

namespace {

// Ids become file and folder names (DIR/<id>/labels.json, <id>.npz) and JSON strings: bytes
// that are not UTF-8 become '_', and an id longer than kMaxIdLength keeps a prefix plus 8 hex
// digits of its sha256 (a 300-character id failed with "File name too long").
std::string usableId(const std::string& raw) {
  std::string id;
  for (std::size_t i = 0; i < raw.size();) {
    std::size_t length = 1;
    while (length <= 4 && i + length <= raw.size() &&
           firstInvalidUtf8(std::string_view(raw).substr(i, length)))
      ++length;
    if (length > 4 || i + length > raw.size()) {
      id += '_';
      ++i;
    } else {
      id += raw.substr(i, length);
      i += length;
    }
  }
  if (id.size() > kMaxIdLength) {
    std::size_t cut = kMaxIdLength - 9;
    while (cut > 0 && (static_cast<unsigned char>(id[cut]) & 0xC0) == 0x80) --cut;  // whole chars
    id = id.substr(0, cut) + "-" + sha256Hex(raw).substr(0, 8);
  }
  return id;
}

// "a/b/mesh.obj" -> "a__b", "a/chair.glb" -> "a__chair" (relative to the listed folder).
std::string idFor(const std::filesystem::path& relative) {
  std::filesystem::path stemPath = relative.parent_path();
  if (asciiLower(relative.stem().string()) != "mesh" || stemPath.empty()) {
    stemPath /= relative.stem();
  }
  std::string id;
  for (const auto& part : stemPath) {
    if (!id.empty()) id += "__";
    id += part.string();
  }
  return usableId(id);
}
}  // namespace

std::string objectIdOfFile(const std::filesystem::path& meshFile) {
  const std::string stem =
      asciiLower(meshFile.stem().string()) == "mesh" && meshFile.has_parent_path()
          ? meshFile.parent_path().filename().string()
          : meshFile.stem().string();
  return usableId(stem.empty() ? meshFile.stem().string() : stem);
}

std::vector<MeshFile> findMeshFiles(const std::filesystem::path& fileOrDir) {
  std::error_code ec;
  if (!std::filesystem::exists(fileOrDir, ec))
    throw FileError(fileOrDir, "no such file or directory");
  if (!std::filesystem::is_directory(fileOrDir, ec)) {
    requireRegularFile(fileOrDir);  // a FIFO or a device is named as such, whatever its name
    if (!isMeshFile(fileOrDir)) {
      throw FileError(fileOrDir,
                      "not a supported mesh file (use .obj, .glb, .gltf, .fbx, .dae, "
                      ".ply or .stl)");
    }
    return {{fileOrDir, objectIdOfFile(fileOrDir)}};
  }
  std::vector<std::filesystem::path> found;
  auto it = std::filesystem::recursive_directory_iterator(
      fileOrDir, std::filesystem::directory_options::skip_permission_denied, ec);
  if (ec) throw FileError(fileOrDir, "cannot list folder: " + ec.message());
  for (; it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) throw FileError(fileOrDir, "cannot list folder: " + ec.message());
    const auto name = it->path().filename().string();
    if (!name.empty() && name[0] == '.') {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && isMeshFile(it->path())) found.push_back(it->path());
  }
  std::sort(found.begin(), found.end());
  std::vector<MeshFile> files;
  std::set<std::string> used;
  for (const auto& p : found) {
    std::string id = idFor(std::filesystem::relative(p, fileOrDir));
    // Two meshes in one object folder (mesh.obj and mesh.glb): keep both, distinguishable.
    if (used.count(id)) id += "__" + lowerExtension(p).substr(1);
    used.insert(id);
    files.push_back({p, id});
  }
  return files;
}

}  // namespace sagrid
