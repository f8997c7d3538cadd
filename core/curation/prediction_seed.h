// The starting point of a replayed curation (curation_replay.h): the predictions of an
// `annotate --out PRED` run written beside the meshes they describe, as the GUI opens them.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>

namespace sagrid {

// For every PRED/<id>/labels.json whose mesh (object.mesh, resolved inside `meshRoot`, the
// folder the user named) exists, writes those labels to `labelsPathFor(mesh)` with object.mesh
// the mesh's file name. Returns how many were written. Throws FileError for a labels file that
// cannot be read or a mesh reference leading outside `meshRoot`.
std::size_t seedPredictions(const std::filesystem::path& predictions, const std::filesystem::path& meshRoot,
                            const std::function<std::filesystem::path(const std::filesystem::path&)>& labelsPathFor);

}  // namespace sagrid
