#include "core/export/export_frame.h"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/mesh/mesh_import.h"

namespace sagrid::exportdetail {

namespace fs = std::filesystem;

std::string objectId(const ObjectLabels& labels, const fs::path& meshPath) {
  if (!labels.object.id.empty()) return labels.object.id;
  return meshPath.stem() == "mesh" ? meshPath.parent_path().filename().string()
                                   : meshPath.stem().string();
}

std::string uprightRollPitchYaw(const ObjectLabels& labels) {
  switch (upAxisOrZ(labels.object.up)) {
    case UpAxis::PosX: return "0 -1.5707963 0";
    case UpAxis::NegX: return "0 1.5707963 0";
    case UpAxis::PosY: return "1.5707963 0 0";
    case UpAxis::NegY: return "-1.5707963 0 0";
    case UpAxis::NegZ: return "3.1415927 0 0";
    default: return "0 0 0";
  }
}

std::string uprightQuaternion(const ObjectLabels& labels) {
  switch (upAxisOrZ(labels.object.up)) {
    case UpAxis::PosX: return "0.7071068 0 -0.7071068 0";
    case UpAxis::NegX: return "0.7071068 0 0.7071068 0";
    case UpAxis::PosY: return "0.7071068 0.7071068 0 0";
    case UpAxis::NegY: return "0.7071068 -0.7071068 0 0";
    case UpAxis::NegZ: return "0 1 0 0";
    default: return "";
  }
}

Eigen::Vector3f toSimulatorFrame(const ObjectLabels& labels, const Eigen::Vector3f& filePosition) {
  return fileToZUp(filePosition, upAxisOrZ(labels.object.up)) *
         static_cast<float>(metersPerUnit(labels));
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

fs::path copyMeshWithDependencies(const fs::path& mesh, const fs::path& dir,
                                  const std::string& newName) {
  std::error_code ec;
  if (!fs::is_regular_file(mesh, ec)) throw FileError(mesh, "mesh file not found");
  const fs::path target = dir / (newName.empty() ? mesh.filename().string() : newName);
  copyFileAtomic(mesh, target);
  std::string ext = mesh.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj") {
    const fs::path source = mesh.parent_path();
    for (const auto& mtl : referencedFiles(mesh, {"mtllib"})) {
      if (!fs::is_regular_file(source / mtl, ec)) continue;  // the importer already warned
      copyFileAtomic(source / mtl, dir / mtl);
      for (const auto& texture :
           referencedFiles(source / mtl, {"map_Kd", "map_Ka", "map_Bump", "bump", "map_d"})) {
        if (fs::is_regular_file(source / texture, ec))
          copyFileAtomic(source / texture, dir / texture);
      }
    }
  }
  return target;
}

std::string formatNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

}  // namespace sagrid::exportdetail
