// Decoding of KHR_draco_mesh_compression primitives (Debian's libdraco): the compressed bytes of a
// primitive become its triangles' indices and the attributes the extension names, in glTF's
// attribute names ("POSITION", "TEXCOORD_0", ...).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace sagrid {

struct DracoAttribute {
  int components = 0;
  std::vector<double> values;  // points * components
};

struct DecodedDracoPrimitive {
  std::size_t points = 0;
  std::vector<std::uint32_t> indices;  // three per triangle
  std::map<std::string, DracoAttribute> attributes;
};

// Decodes `bytes` as a Draco mesh and reads each attribute of `attributeIds` (glTF name -> Draco
// unique id). Throws InvalidArgument saying what is wrong (not Draco, truncated, a named
// attribute missing); the caller adds the file and primitive.
DecodedDracoPrimitive decodeDracoPrimitive(std::string_view bytes,
                                           const std::map<std::string, int>& attributeIds);

}  // namespace sagrid
