// Some triangles of a mesh as a mesh of their own: only the vertices they use (renumbered in
// order), with every per-vertex attribute, their materials, and the mesh's materials, textures and
// file bookkeeping, so the subset renders and exports like the original. A control part cut from
// an object's body is one subset, the body less the part the other.
#pragma once

#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid {

// The triangles t with keep[t] (a shorter `keep` keeps none beyond it); triangles with an
// out-of-range index are left out.
Mesh triangleSubset(const Mesh& mesh, const std::vector<bool>& keep);

}  // namespace sagrid
