#include "core/export/training_set.h"

#include <cctype>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "core/common/ascii_case.h"
#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/common/error.h"
#include "core/dataset/object_source.h"
#include "core/export/export_frame.h"

namespace sagrid {

namespace fs = std::filesystem;

namespace {
std::string datasetId(const std::string& text) {
  std::string id;
  for (unsigned char c : text)
    id.push_back(std::isalnum(c) || c == '-' || c == '_' ? static_cast<char>(c) : '-');
  return safeFileName(id);  // bounded length; '-' for everything but letters, digits, - and _
}
}  // namespace

TrainingSetEntry addToTrainingSet(const ObjectLabels& labels, const fs::path& meshPath,
                                  const fs::path& labelsPath, const fs::path& datasetDir) {
  if (labels.object.category.empty()) {
    throw InvalidArgument(meshPath.string() +
                          ": set the object's category before adding it to a training set");
  }
  exportdetail::containedMeshReferences(meshPath);  // refuse before anything is created
  TrainingSetEntry entry;
  entry.id = datasetId(exportdetail::objectId(labels, meshPath));
  const fs::path objectDir = datasetDir / entry.id;
  std::error_code ec;
  fs::create_directories(objectDir, ec);
  if (ec) throw FileError(objectDir, "cannot create folder: " + ec.message());

  const std::string ext = lowerExtension(meshPath);
  entry.mesh = exportdetail::copyMeshWithDependencies(meshPath, objectDir, "mesh" + ext);
  // The record of where the mesh comes from goes with it: its source (leave-one-source-out guards
  // fold by it) and what it declares (units, up axis) stay the object's.
  const fs::path record = meshPath.parent_path() / kProvenanceRecordFile;
  if (fs::is_regular_file(record, ec)) {
    fs::copy_file(record, objectDir / kProvenanceRecordFile, fs::copy_options::overwrite_existing, ec);
    if (ec) throw FileError(objectDir / kProvenanceRecordFile, "cannot copy the provenance record: " + ec.message());
  }

  ObjectLabels copy = labels;
  copy.object.id = entry.id;
  copy.object.mesh = entry.mesh.filename().string();
  copy.extra["provenance"] = {
      {"mesh", fs::absolute(meshPath).lexically_normal().string()},
      {"labels",
       labelsPath.empty() ? std::string() : fs::absolute(labelsPath).lexically_normal().string()},
      {"added", currentUtcTimestamp()},
      {"tool", std::string("sagrid ") + SAGRID_VERSION}};
  entry.labels = objectDir / "labels.json";
  writeLabels(entry.labels, copy);

  // Manifest: one JSON line per object; an existing line for this id is replaced.
  const fs::path manifest = datasetDir / "manifest.jsonl";
  std::ostringstream out;
  if (fs::exists(manifest, ec)) {
    std::istringstream in(readFileBytes(manifest));
    std::string line;
    while (std::getline(in, line)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      try {
        if (nlohmann::json::parse(line).value("id", "") == entry.id) continue;
      } catch (const nlohmann::json::exception&) {
        throw FileError(manifest, "a line is not JSON; fix or remove it before adding objects");
      }
      out << line << "\n";
    }
  }
  const nlohmann::json line = {{"id", entry.id},
                               {"category", labels.object.category},
                               {"mesh", entry.id + "/" + entry.mesh.filename().string()},
                               {"labels", entry.id + "/labels.json"}};
  out << line.dump() << "\n";
  writeFileAtomic(manifest, out.str());
  return entry;
}

}  // namespace sagrid
