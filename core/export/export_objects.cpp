#include "core/export/export_objects.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "core/common/contained_paths.h"
#include "core/common/error.h"
#include "core/export/mjcf_export.h"
#include "core/export/omnigibson_export.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

namespace fs = std::filesystem;

fs::path meshForLabels(const ObjectLabels& labels, const fs::path& labelsPath) {
  const fs::path dir = labelsPath.parent_path().empty() ? fs::path(".") : labelsPath.parent_path();
  if (!labels.object.mesh.empty()) return resolveContained(dir, labels.object.mesh, labelsPath);
  std::error_code ec;
  std::vector<fs::path> items;
  for (const auto& item : fs::directory_iterator(dir, ec)) items.push_back(item.path());
  std::sort(items.begin(), items.end());  // the same mesh every run
  for (const auto& path : items) {
    std::string ext = path.extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const auto& supported = supportedMeshExtensions();
    if (std::find(supported.begin(), supported.end(), ext) != supported.end()) return path;
  }
  throw FileError(labelsPath, "no mesh named in object.mesh and none found beside it");
}

namespace {

std::vector<fs::path> labelFiles(const fs::path& input) {
  std::error_code ec;
  if (fs::is_regular_file(input, ec)) {
    if (input.extension() == ".json") return {input};
    return {input.parent_path() / "labels.json"};  // a mesh: its labels sit beside it
  }
  if (!fs::is_directory(input, ec)) throw FileError(input, "no such file or folder");
  std::vector<fs::path> found;
  if (fs::is_regular_file(input / "labels.json", ec)) found.push_back(input / "labels.json");
  for (const auto& item : fs::directory_iterator(input, ec)) {
    if (item.is_directory(ec) && fs::is_regular_file(item.path() / "labels.json", ec)) {
      found.push_back(item.path() / "labels.json");
    }
  }
  std::sort(found.begin(), found.end());
  if (found.empty()) throw FileError(input, "no labels.json in this folder or its subfolders");
  return found;
}

}  // namespace

std::vector<SimulatorExport> exportObjects(const fs::path& input, const std::string& format,
                                           const fs::path& outDir, const ExportOptions& options) {
  if (format != "omnigibson" && format != "mjcf") {
    throw InvalidArgument("unknown export format '" + format + "' (use omnigibson or mjcf)");
  }
  ExportNames names;
  ExportOptions batch = options;
  if (!batch.names) batch.names = &names;
  std::vector<SimulatorExport> results;
  for (const auto& labelsPath : labelFiles(input)) {
    const ObjectLabels labels = readLabels(labelsPath);
    const fs::path mesh = meshForLabels(labels, labelsPath);
    results.push_back(format == "mjcf" ? exportMjcf(labels, mesh, outDir, batch, labelsPath)
                                       : exportOmniGibson(labels, mesh, outDir, batch, labelsPath));
  }
  return results;
}

}  // namespace sagrid
