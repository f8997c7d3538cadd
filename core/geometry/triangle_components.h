// Which connected component each triangle of a mesh belongs to: triangles joined through shared
// vertices, where vertices at the same position count as one (importers split them at seams of
// normals and UVs). Split by material, a vertex is shared only by triangles of one material, so a
// knob drawn in its own material on a fused body is a component of its own.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace sagrid {

struct Mesh;

struct TriangleComponents {
  // Per triangle its component, numbered in the order of each component's first triangle; -1 for a
  // triangle with an out-of-range index.
  std::vector<int> ofTriangle;
  int count = 0;
  // The welded vertices: each distinct (position, material when split) once, and per triangle
  // its corners' welded ids (unset for a triangle with an out-of-range index).
  std::vector<Eigen::Vector3f> weldedPositions;
  std::vector<std::array<int, 3>> weldedCorners;
};

TriangleComponents triangleComponents(const Mesh& mesh, bool splitByMaterial = false);

}  // namespace sagrid
