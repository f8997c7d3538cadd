#include "core/dataset/dataset.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/dataset/labels_mesh.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {
namespace fs = std::filesystem;

fs::path findMeshFile(const fs::path& dir) {
  for (const auto& ext : supportedMeshExtensions())
    if (fs::is_regular_file(dir / ("mesh" + ext))) return dir / ("mesh" + ext);
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && isMeshFile(e.path())) found.push_back(e.path());
  return found.size() == 1 ? found.front() : fs::path();
}

std::vector<DatasetEntry> readDataset(const fs::path& directory, const fs::path& referenceRoot) {
  if (!fs::is_directory(directory)) throw FileError(directory, "dataset folder not found");
  std::vector<DatasetEntry> entries;
  const fs::path manifest = directory / "manifest.jsonl";
  if (fs::is_regular_file(manifest)) {
    std::istringstream lines(readFileBytes(manifest));
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
      ++number;
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      try {
        const auto j = nlohmann::json::parse(line);
        DatasetEntry e;
        e.id = j.at("id").get<std::string>();
        e.category = j.value("category", "");
        const std::string where = manifest.string() + " line " + std::to_string(number);
        e.mesh = resolveReferenceWithin(directory, j.at("mesh").get<std::string>(), where,
                                        referenceRoot);
        e.labels = resolveReferenceWithin(
            directory, j.value("labels", e.id + "/labels.json"), where, referenceRoot);
        entries.push_back(std::move(e));
      } catch (const nlohmann::json::exception& ex) {
        throw FileError(manifest, "line " + std::to_string(number) +
                                      ": expected {\"id\",\"category\",\"mesh\",\"labels\"} (" +
                                      ex.what() + ")");
      }
    }
    return entries;
  }
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(directory))
    if (e.is_directory() && fs::is_regular_file(e.path() / "labels.json")) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  for (const auto& d : dirs) {
    DatasetEntry e;
    e.id = d.filename().string();
    e.labels = d / "labels.json";
    e.mesh = findMeshFile(d);
    if (e.mesh.empty()) continue;
    e.category = readLabels(e.labels).object.category;
    entries.push_back(std::move(e));
  }
  return entries;
}

}  // namespace sagrid
