// Opens one queued object as an AnnotationDocument: imports the mesh (honouring the up axis the
// labels record) and reads its labels.json, or starts empty labels describing the mesh.
#pragma once

#include <filesystem>
#include <memory>

#include "ui/document/annotation_document.h"

namespace sagrid::ui {

// Throws sagrid::Error (FileError naming the file) for unreadable meshes or labels.
std::unique_ptr<AnnotationDocument> openDocument(const std::filesystem::path& mesh,
                                                 const std::filesystem::path& labels);

}  // namespace sagrid::ui
