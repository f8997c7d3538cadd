#include "core/eval/units_cases.h"

#include <utility>

#include "core/annotate/units_record.h"
#include "core/dataset/dataset.h"
#include "core/dataset/object_source.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "core/mesh/size_measures.h"

namespace sagrid {

std::vector<UnitsCase> readUnitsCases(
    const std::vector<std::filesystem::path>& dataFolders, const FeatureOptions& options,
    const std::function<void(std::size_t, std::size_t, const std::string&)>& progress,
    std::size_t* unconfirmed) {
  std::vector<std::pair<DatasetEntry, std::string>> entries;
  for (const auto& folder : dataFolders)
    for (auto& entry : readDataset(folder)) entries.emplace_back(std::move(entry), folder.filename().string());
  std::vector<UnitsCase> cases;
  std::size_t done = 0;
  for (const auto& [entry, folderName] : entries) {
    const ObjectLabels labels = readLabels(entry.labels);
    if (recordedUnitGuess(labels.object)) {
      if (unconfirmed) ++*unconfirmed;
      if (progress) progress(++done, entries.size(), entry.id);
      continue;
    }
    const std::optional<UpAxis> up = options.up ? options.up : declaredUpAxis(entry.mesh);
    const Mesh mesh = importMesh(entry.mesh, ImportOptions(up, /*detect=*/true));
    FeatureOptions framed = options;
    framed.up = mesh.fileUp;
    UnitsCase c;
    c.group = folderName;
    c.object.units = measureSizes(mesh);
    c.object.metersPerUnit = metersPerUnit(labels);
    c.object.id = entry.id;
    c.object.source = objectSource(labels, entry.mesh, folderName);
    const std::string category = entry.category.empty() ? labels.object.category : entry.category;
    c.object.category = category == "stove" || category == "sink" ? category : "none";
    c.object.descriptor = framed.cacheDir.empty() ? computeFeatures(mesh, framed).descriptor
                                                   : extractFeatures(entry.mesh, framed).descriptor;
    if (c.object.meters(SizeMeasure::LargestExtent) > 0) cases.push_back(std::move(c));
    if (progress) progress(++done, entries.size(), entry.id);
  }
  return cases;
}

}  // namespace sagrid
