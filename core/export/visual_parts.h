// The visual mesh of an MJCF export as MuJoCo can load it whole: one part per material (its own
// STL file and colour), each with >= 4 vertices that are not all in one plane, so every triangle
// reaches the simulator (MuJoCo reads only the first o/g group of an OBJ, and refuses meshes of
// no volume wherever it has to compute one).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid::exportdetail {

struct MeshPart {
  std::string name;  // "visual_<i>", safe for file and MJCF names
  Mesh mesh;         // positions and triangles only
  Eigen::Vector3f color{0.8f, 0.8f, 0.8f};
};

// True when the mesh has >= 4 vertices and they span a volume (not all in one plane).
bool spansVolume(const Mesh& mesh);

// Splits `mesh` by material. Parts that do not span a volume are merged together, and into the
// largest part if still flat; a whole object that is flat stays one part and gets a warning.
// Every triangle of `mesh` is in exactly one part.
std::vector<MeshPart> visualParts(const Mesh& mesh, std::vector<std::string>& warnings);

}  // namespace sagrid::exportdetail
