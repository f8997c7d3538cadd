#include "ui/document/object_loader.h"

#include <optional>
#include <system_error>

#include "core/annotate/units_record.h"
#include "core/dataset/object_source.h"
#include "core/mesh/mesh_import.h"

namespace sagrid::ui {

namespace fs = std::filesystem;

std::unique_ptr<AnnotationDocument> openDocument(const fs::path& meshPath,
                                                 const fs::path& labelsPath) {
  std::error_code ec;
  std::optional<ObjectLabels> existing;
  if (fs::exists(labelsPath, ec)) existing = readLabels(labelsPath);

  // A labelled object keeps its labels' axis and units; a new one takes the axis and units its
  // provenance.json declares, else the axis detected from the geometry.
  std::optional<UpAxis> up = existing ? upAxisOrZ(existing->object.up) : declaredUpAxis(meshPath);
  auto mesh = std::make_shared<Mesh>(importMesh(meshPath, ImportOptions(up, /*detect=*/!existing)));

  ObjectLabels labels;
  if (existing) {
    labels = std::move(*existing);
    if (labels.object.mesh.empty()) labels.object.mesh = meshPath.filename().string();
    if (labels.object.sha256.empty()) labels.object.sha256 = mesh->sha256;
  } else {
    // Dataset layout DIR/<id>/mesh.ext (labels.json beside it) names the object after its
    // folder, whatever the mesh is called: two libraries' frigo.obj are two objects.
    const bool ownFolder = labelsPath.filename() == "labels.json" &&
                           labelsPath.parent_path() == meshPath.parent_path();
    const bool genericName = meshPath.stem() == "mesh";
    labels.object.id = (ownFolder || genericName) ? meshPath.parent_path().filename().string()
                                                  : meshPath.stem().string();
    labels.object.mesh = meshPath.filename().string();
    labels.object.sha256 = mesh->sha256;
    labels.object.up = toString(mesh->fileUp);
    if (mesh->fileUpDetected) labels.object.upConfidence = mesh->fileUpConfidence;
    // Units the record declares stand from the start: the prediction's guess is only taken where
    // none are known, and the mass shown before it returns uses them.
    if (const auto scale = declaredMetersPerUnit(meshPath))
      recordDeclaredUnits(labels.object, *scale, "provenance.json");
  }
  return std::make_unique<AnnotationDocument>(std::move(mesh), std::move(labels), labelsPath,
                                              meshPath);
}

}  // namespace sagrid::ui
