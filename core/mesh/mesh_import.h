// Mesh import with assimp: OBJ (+MTL and textures), glTF/GLB, FBX, DAE, PLY, STL. All nodes are
// merged into one triangle mesh with their transforms applied, turned z-up (glTF/GLB are y-up by
// their spec), with per-vertex normals, UVs, colours, materials and decoded textures, and the
// sha256 of the file's bytes. Every problem with the file is a one-line FileError.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid {

struct ImportOptions {
  // The file's up axis; when unset, y for glTF/GLB (and FBX files that declare y-up), else z.
  std::optional<UpAxis> up;

  ImportOptions(std::optional<UpAxis> upAxis = std::nullopt) : up(upAxis) {}  // NOLINT: implicit
};

// Throws FileError ("path: problem") for a missing file, a directory, an unsupported extension,
// an empty or corrupt file, no triangles, only degenerate triangles, NaN/Inf coordinates, and
// coordinates that cannot be normalized (see normalizationProblem).
Mesh importMesh(const std::filesystem::path& path, const ImportOptions& options = {});

// Lower-case extensions importMesh accepts, with the dot (".obj", ".glb", ...).
const std::vector<std::string>& supportedMeshExtensions();

// Parses "y" / "z" (as in --up and labels object.up); nullopt for anything else.
std::optional<UpAxis> parseUpAxis(const std::string& text);
const char* toString(UpAxis up);

}  // namespace sagrid
