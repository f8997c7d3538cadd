// Checks of a mesh file's bytes before assimp parses them. Assimp recurses once per glTF node
// (20,000 nested nodes overflow the stack), aborts on a truncated ASCII PLY, spins on a binary
// PLY cut inside its header, and allocates whatever element count or chunk length a header
// declares. So the structure a header promises is compared with the file's size first, node and
// element nesting is bounded, and the content must match the extension (OBJ text named .glb
// would otherwise load as y-up glTF). Every refusal is a FileError naming the file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace sagrid {

// Deepest glTF node hierarchy or COLLADA element nesting accepted; real assets stay below 50.
inline constexpr int kMaxSceneDepth = 256;

struct MeshFileFacts {
  // Triangles the file's faces declare, where the format makes that cheap to count (OBJ, PLY):
  // an import that yields fewer read the file only partly.
  std::optional<std::size_t> declaredTriangles;
  // Evidence that the file was cut short but can still be read in part (an OBJ whose last line
  // stops mid-statement), e.g. "ends in the middle of a line"; empty when there is none.
  std::string truncation;
};

// The format the bytes hold, as a user would name it ("binary glTF (GLB)", "OBJ text", "PLY",
// "glTF JSON", "COLLADA XML", "binary FBX", "binary STL", "ASCII STL", "a zip archive"), or ""
// when it is not recognized.
std::string sniffMeshFormat(std::string_view bytes);

// Throws FileError naming `path` when the content does not match `extension` (lower case, with
// the dot) or its structure is unsafe to hand to assimp (see above). Returns what it learnt.
MeshFileFacts checkMeshFile(std::string_view bytes, const std::string& extension,
                            const std::filesystem::path& path);

}  // namespace sagrid
