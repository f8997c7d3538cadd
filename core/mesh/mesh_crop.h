// The part of a mesh inside a box: triangles inside are kept as they are, triangles crossing the
// box are clipped to it (vertex normals, UVs and colours interpolated), materials and textures
// kept, so the crop renders like the original. Positions keep the mesh's own (z-up) frame, so
// points found on the crop are points of the original mesh. Large triangles matter: a counter
// top of two triangles still surrounds a cropped tap.
#pragma once

#include <Eigen/Geometry>

#include "core/mesh/mesh.h"

namespace sagrid {

// An empty mesh (no triangles) when nothing of the mesh lies in `box`.
Mesh cropMesh(const Mesh& mesh, const Eigen::AlignedBox3f& box);

}  // namespace sagrid
