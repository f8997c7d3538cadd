// Binary STL, the mesh format MuJoCo reads whole (it takes only the first o/g group of an OBJ):
// one file per mesh part, positions as written (z-up metres for the exporters).
#pragma once

#include <string>

#include "core/mesh/mesh.h"

namespace sagrid::exportdetail {

// 80-byte header, triangle count, then per triangle its unit normal, three vertices and a zero
// attribute word, little-endian floats. Throws Error for non-finite positions.
std::string encodeBinaryStl(const Mesh& mesh);

}  // namespace sagrid::exportdetail
