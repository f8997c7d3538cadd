// SHA-256 of byte strings, as lowercase hex. Meshes are identified by the hash of their file bytes
// (labels object.sha256, feature caches), so writers and importers must agree on it.
#pragma once

#include <string>
#include <string_view>

namespace sagrid {

std::string sha256Hex(std::string_view bytes);

}  // namespace sagrid
