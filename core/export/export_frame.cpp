#include "core/export/export_frame.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/common/ascii_case.h"
#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/common/error.h"
#include "core/mesh/mesh_import.h"

namespace sagrid::exportdetail {

namespace fs = std::filesystem;

std::string objectId(const ObjectLabels& labels, const fs::path& meshPath) {
  if (!labels.object.id.empty()) return labels.object.id;
  return meshPath.stem() == "mesh" ? meshPath.parent_path().filename().string()
                                   : meshPath.stem().string();
}

Eigen::Vector3f toSimulatorFrame(const ObjectLabels& labels, const Eigen::Vector3f& filePosition,
                                 double metersPerUnit) {
  return fileToZUp(filePosition, upAxisOrZ(labels.object.up)) * static_cast<float>(metersPerUnit);
}

namespace {

void copyFileAtomic(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_directories(to.parent_path(), ec);
  writeFileAtomic(to, readFileBytes(from));
}

// Names after a keyword on lines such as "mtllib a.mtl" or "map_Kd tex/wood.png" (last token).
std::vector<std::string> referencedFiles(const fs::path& file,
                                         const std::vector<std::string>& keywords) {
  std::vector<std::string> found;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    for (const auto& k : keywords) {
      if (keyword == k) {
        std::string rest, last;
        while (words >> rest) last = rest;
        if (!last.empty()) found.push_back(last);
      }
    }
  }
  return found;
}

}  // namespace

std::vector<fs::path> containedMeshReferences(const fs::path& mesh) {
  const std::string ext = lowerExtension(mesh);
  std::vector<fs::path> files;
  std::error_code ec;
  if (ext != ".obj" || !fs::is_regular_file(mesh, ec)) return files;
  const fs::path source = mesh.parent_path().empty() ? fs::path(".") : mesh.parent_path();
  for (const auto& mtlName : referencedFiles(mesh, {"mtllib"})) {
    const fs::path mtl = resolveContained(source, mtlName, mesh);
    if (!fs::is_regular_file(mtl, ec)) continue;  // the importer warns about missing ones
    files.push_back(mtl);
    const fs::path mtlFolder = mtl.lexically_relative(source).parent_path();
    for (const auto& textureName :
         referencedFiles(mtl, {"map_Kd", "map_Ka", "map_Ks", "map_Bump", "map_bump", "bump",
                               "map_d", "disp", "decal", "refl", "norm"})) {
      // MTL texture names are relative to the MTL's folder, which lies inside the mesh's.
      const fs::path texture =
          resolveContained(source, (mtlFolder / textureName).generic_string(), mtl);
      if (fs::is_regular_file(texture, ec)) files.push_back(texture);
    }
  }
  return files;
}

fs::path copyMeshWithDependencies(const fs::path& mesh, const fs::path& dir,
                                  const std::string& newName) {
  std::error_code ec;
  if (!fs::is_regular_file(mesh, ec)) throw FileError(mesh, "mesh file not found");
  const std::vector<fs::path> references = containedMeshReferences(mesh);  // refuses first
  const fs::path target = dir / (newName.empty() ? mesh.filename().string() : newName);
  copyFileAtomic(mesh, target);
  const fs::path source = mesh.parent_path().empty() ? fs::path(".") : mesh.parent_path();
  for (const auto& file : references) copyFileAtomic(file, dir / file.lexically_relative(source));
  return target;
}

std::string formatNumber(double value) {
  if (!std::isfinite(value))
    throw Error("internal error: a non-finite number reached an export file");
  if (value == 0.0) value = 0.0;  // no "-0"
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string formatVector(const Eigen::Vector3d& v) {
  return formatNumber(v.x()) + " " + formatNumber(v.y()) + " " + formatNumber(v.z());
}

}  // namespace sagrid::exportdetail
