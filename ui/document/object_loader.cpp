#include "ui/document/object_loader.h"

#include <optional>
#include <system_error>

#include "core/mesh/mesh_import.h"

namespace sagrid::ui {

namespace fs = std::filesystem;

std::unique_ptr<AnnotationDocument> openDocument(const fs::path& meshPath,
                                                 const fs::path& labelsPath) {
  std::error_code ec;
  std::optional<ObjectLabels> existing;
  if (fs::exists(labelsPath, ec)) existing = readLabels(labelsPath);

  std::optional<UpAxis> up;
  if (existing) up = existing->object.up == "y" ? UpAxis::Y : UpAxis::Z;
  auto mesh = std::make_shared<Mesh>(importMesh(meshPath, up));

  ObjectLabels labels;
  if (existing) {
    labels = std::move(*existing);
    if (labels.object.mesh.empty()) labels.object.mesh = meshPath.filename().string();
    if (labels.object.sha256.empty()) labels.object.sha256 = mesh->sha256;
  } else {
    // Dataset layout DIR/<id>/mesh.ext names the object after its folder.
    const bool genericName = meshPath.stem() == "mesh";
    labels.object.id =
        genericName ? meshPath.parent_path().filename().string() : meshPath.stem().string();
    labels.object.mesh = meshPath.filename().string();
    labels.object.sha256 = mesh->sha256;
    labels.object.up = mesh->fileUp == UpAxis::Y ? "y" : "z";
  }
  return std::make_unique<AnnotationDocument>(std::move(mesh), std::move(labels), labelsPath,
                                              meshPath);
}

}  // namespace sagrid::ui
