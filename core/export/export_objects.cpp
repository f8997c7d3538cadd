#include "core/export/export_objects.h"

#include <algorithm>
#include <system_error>

#include "core/common/error.h"
#include "core/dataset/labels_mesh.h"
#include "core/export/mjcf_export.h"
#include "core/export/omnigibson_export.h"

namespace sagrid {

namespace fs = std::filesystem;

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
    const fs::path mesh = meshForLabels(labels, labelsPath, options.meshRoot);
    results.push_back(format == "mjcf" ? exportMjcf(labels, mesh, outDir, batch, labelsPath)
                                       : exportOmniGibson(labels, mesh, outDir, batch, labelsPath));
  }
  return results;
}

}  // namespace sagrid
