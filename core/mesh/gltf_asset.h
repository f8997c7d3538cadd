// A glTF 2.0 asset as its file holds it: the JSON document and the bytes of every buffer, from the
// GLB's binary chunk, from data URIs, or from files inside the mesh's own folder. The glTF reader
// (gltf_plain.h) reads buffer views and accessors from here, decoding EXT_meshopt_compression
// views, and writes the plain GLB it hands to assimp with writeGlb. Every problem is a FileError
// naming the mesh file and the glTF element ("accessor 3", "buffer view 7").
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sagrid {

struct GltfAsset {
  std::filesystem::path path;  // the mesh file, for messages and relative references
  nlohmann::json document;
  // One entry per buffers[] element. A buffer without data of its own (an EXT_meshopt_compression
  // fallback) is empty.
  std::vector<std::string> buffers;
};

// Parses a .glb (binary) or .gltf (JSON) file's bytes and reads every buffer it declares. The
// GLB's structure was checked by checkMeshFile. Throws FileError for malformed JSON, a buffer
// whose file is missing or outside the mesh's folder, or that holds fewer bytes than it declares.
GltfAsset readGltfAsset(std::string_view bytes, const std::filesystem::path& path);

// The JSON document alone (no buffer read): what the extension checks need.
nlohmann::json readGltfDocument(std::string_view bytes, const std::filesystem::path& path);

// The bytes a buffer or image `uri` names: a data URI's, or a file's inside the mesh's folder
// (percent-escapes decoded). nullopt when the file is missing. Throws FileError naming `where` for
// a malformed data URI or a path that leaves the folder.
std::optional<std::string> referencedBytes(const GltfAsset& asset, const std::string& uri, const std::string& where);

// The bytes of buffer view `view`: a slice of its buffer, or for an EXT_meshopt_compression view
// the decoded data. Throws FileError when the view lies outside its buffer or does not decode.
std::string bufferViewBytes(const GltfAsset& asset, std::size_t view);

// Values of an accessor as doubles, `components` per element (1 for SCALAR ... 16 for MAT4),
// normalized integers mapped to [0,1] or [-1,1] as the spec says, sparse substitution applied.
struct AccessorValues {
  std::size_t count = 0;
  int components = 0;
  std::vector<double> values;  // count * components
};
AccessorValues readAccessor(const GltfAsset& asset, std::size_t accessor);

// Number of components of an accessor type ("VEC3" -> 3); 0 for an unknown type.
int accessorComponents(std::string_view type);

// A GLB file of `document` with `binary` as its one buffer (buffers[] is set to it).
std::string writeGlb(nlohmann::json document, const std::string& binary);

// The element `array`[index] of the document (e.g. "accessors", 3), or a FileError naming it.
const nlohmann::json& gltfElement(const GltfAsset& asset, const char* array, std::size_t index);

}  // namespace sagrid
