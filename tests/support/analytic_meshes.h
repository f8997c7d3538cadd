// Small meshes with known geometry for tests: UV spheres, axis-aligned boxes and quads, cylinders, with
// exact normals and a plain colour.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid::test {

// Sphere of `radius` around `centre`, `rings` latitude bands x 2*rings longitude segments.
Mesh uvSphere(const Eigen::Vector3f& centre, float radius, int rings = 48);
// Axis-aligned box from lo to hi, 12 outward-facing triangles.
Mesh box(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi);
// Closed cylinder of `radius` and `height` about z from the origin up, `segments` around (a round
// knob), every vertex turned by `turn` and then moved by `offset`.
Mesh cylinder(float radius, float height, int segments,
              const Eigen::Matrix3f& turn = Eigen::Matrix3f::Identity(),
              const Eigen::Vector3f& offset = Eigen::Vector3f::Zero());
// Axis-aligned quad at height z over [lo, hi] in x and y, facing +z, with UVs over [0,1]^2.
Mesh quadZ(const Eigen::Vector2f& lo, const Eigen::Vector2f& hi, float z);
// A plate of cellsX x cellsY cells of 0.1 on shared vertices (one connected body) at z = 0, its
// vertices with i0 <= i <= i1 and j0 <= j <= j1 of each of `plateaus` ({i0, i1, j0, j1}) raised
// by `rise`: plateaus meeting the plate through slopes one cell wide (45 degrees for a rise of
// 0.1), as a burner's ring modelled into a hob.
Mesh plateWithPlateaus(int cellsX, int cellsY, float rise,
                       const std::vector<std::array<int, 4>>& plateaus);
// Appends b to a (indices offset); materials and colours of b are kept when present.
void append(Mesh& a, const Mesh& b);
// Gives every vertex the colour `rgb`.
void paint(Mesh& mesh, const Eigen::Vector3f& rgb);
// Exact distance from p to the mesh by brute force over all triangles, independent of any BVH.
float bruteForceDistance(const Mesh& mesh, const Eigen::Vector3f& p);

}  // namespace sagrid::test
