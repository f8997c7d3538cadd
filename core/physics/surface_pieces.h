// The mesh surface cut into voxels, kept as a few extreme points per voxel: for each voxel the
// triangles cross, the points of the clipped pieces that reach farthest along 14 directions
// (the 6 axes and 8 diagonals). The convex hull of a set of voxels' points is then (to within a
// small part of a voxel) the hull of the exact surface inside those voxels, and two voxel sets
// cut apart at a voxel face get hulls that meet at that face.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/grid/normalization.h"

namespace sagrid {

struct Mesh;

namespace physics {

class SurfacePieces {
 public:
  // Points are in grid units: voxel (i, j, k) spans [i, i+1] x [j, j+1] x [k, k+1] of the
  // normalized frame mapped by (p + 0.5) * resolution.
  SurfacePieces(const Mesh& mesh, const Normalization& normalization, int resolution);

  // The extreme points of the surface in the voxel with this linear index (empty when none).
  const std::vector<Eigen::Vector3f>& points(std::size_t voxel) const;
  bool crossesVoxel(std::size_t voxel) const { return m_slot[voxel] >= 0; }

 private:
  std::vector<std::int32_t> m_slot;  // per voxel: index into m_points or -1
  std::vector<std::vector<Eigen::Vector3f>> m_points;
};

}  // namespace physics
}  // namespace sagrid
