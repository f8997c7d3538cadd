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

// The default of ImportOptions::lenient: the command line's --lenient sets it for the run.
void setLenientImportByDefault(bool lenient);
bool lenientImportByDefault();

struct ImportOptions {
  // The file's up axis; when unset, y for glTF/GLB (and FBX files that declare y-up), else z,
  // unless detectUp.
  std::optional<UpAxis> up;
  // With `up` unset: choose the up axis from the geometry (detectUpAxis) for formats that do not
  // fix it (OBJ, PLY, STL); FBX/DAE keep their declared axis unless the geometry contradicts it
  // with confidence >= kOverrideDeclaredUpConfidence. glTF/GLB are always y-up. Off by default so
  // datasets, caches and trained models keep reading files exactly as before.
  bool detectUp = false;
  // A file that was cut short but still reads in part (an OBJ ending mid-line, fewer triangles
  // than its faces declare) is an error unless lenient; then a warning says how much was read.
  bool lenient = lenientImportByDefault();

  ImportOptions(std::optional<UpAxis> upAxis = std::nullopt, bool detect = false)  // NOLINT
      : up(upAxis), detectUp(detect) {}
};

constexpr float kOverrideDeclaredUpConfidence = 0.9f;
// Below this detection confidence an OBJ/PLY/STL keeps its format's usual up axis (recorded with
// that axis' probability as its confidence): a wrong turn costs more than a kept convention.
constexpr float kMinDetectedUpConfidence = 0.1f;
// The usual up axis of files whose format does not fix one, when detection is unsure: y for
// Wavefront OBJ (Blender's and Sweet Home 3D's exports, most OBJ in the wild), z (SAGrid's frame)
// for PLY and STL. Without detection, every such file is read z-up as before.
UpAxis unsureUpAxis(const std::string& extension);

// Throws FileError ("path: problem") for a missing file, anything but a regular file, an
// unsupported extension, content that does not match the extension, an empty, corrupt,
// truncated or unsafe file (checkMeshFile), no triangles, only degenerate triangles, coordinates
// that are not finite or beyond kMaxCoordinate, and coordinates that cannot be normalized (see
// normalizationProblem). Referenced files (MTL, .bin, textures) are read only from inside the
// mesh's folder.
Mesh importMesh(const std::filesystem::path& path, const ImportOptions& options = {});

// Lower-case extensions importMesh accepts, with the dot (".obj", ".glb", ...).
const std::vector<std::string>& supportedMeshExtensions();
// True when `path` has one of those extensions (case-blind).
bool isMeshFile(const std::filesystem::path& path);

// Parses an up axis as in --up and labels object.up: "x", "-x", "y", "-y", "z", "-z" (a leading
// "+" and upper case accepted); nullopt for anything else.
std::optional<UpAxis> parseUpAxis(const std::string& text);
// "x", "-x", "y", "-y", "z", "-z" (what labels.json stores).
const char* toString(UpAxis up);
// The labels' object.up as an axis; z (SAGrid's default) for text parseUpAxis rejects (labels
// are validated on reading, so that only happens for hand-built labels).
UpAxis upAxisOrZ(const std::string& text);

}  // namespace sagrid
