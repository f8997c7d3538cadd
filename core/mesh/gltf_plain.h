// glTF extensions that in-the-wild files use and assimp 5.2 does not read: a file that uses
// KHR_draco_mesh_compression, EXT_meshopt_compression, KHR_mesh_quantization, EXT_texture_webp,
// KHR_texture_transform or WebP images is rewritten in memory into a plain GLB (float vertex
// attributes, 32-bit indices, every image embedded, the base colour's texture transform baked
// into TEXCOORD_0) that assimp reads like any other. Files that need none of this are left alone,
// so their import is exactly as before. An extension SAGrid cannot read is one FileError naming it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sagrid {

// Extensions the plain rewrite implements.
const std::vector<std::string>& rewrittenGltfExtensions();

// Throws FileError when the glTF (GLB or JSON bytes) requires an extension that SAGrid can neither
// rewrite nor safely ignore (a material or light extension), e.g. KHR_texture_basisu; the message
// names it. Returns the plain GLB when the file needs the rewrite, nullopt when assimp reads it as
// it is. `path` is the mesh file: buffers and images are read only from inside its folder.
std::optional<std::string> plainGlbOf(std::string_view bytes, const std::filesystem::path& path);

}  // namespace sagrid
