// Where a curated object comes from, for leave-one-source-out evaluation (objects of one source
// look alike, so a split inside a source flatters): the repository of a wild-pool object, the
// library of a Sweet Home 3D one, else the dataset folder it was read from.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

// The record of where a mesh comes from, beside it (the corpora write one per object).
inline constexpr const char* kProvenanceRecordFile = "provenance.json";

// labels' object.provenance.repo, else the "repo" or "library" of a provenance.json beside the
// mesh (the corpora write one), else `fallback`.
std::string objectSource(const ObjectLabels& labels, const std::filesystem::path& mesh, const std::string& fallback);

// The metres per file unit a provenance.json beside the mesh declares (`meters_per_unit` > 0:
// the Sweet Home 3D corpus writes the scale its catalog gives the model); nullopt without one.
std::optional<double> declaredMetersPerUnit(const std::filesystem::path& mesh);

// The up axis a provenance.json beside the mesh declares (`up`: the Sweet Home 3D corpus writes
// "y", its catalogs' convention); nullopt without one or for text that names no axis.
std::optional<UpAxis> declaredUpAxis(const std::filesystem::path& mesh);

}  // namespace sagrid
