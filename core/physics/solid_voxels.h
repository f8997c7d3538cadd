// The solid of a mesh on a voxel grid, shared by the mass estimate and the convex decomposition:
// surface voxels (core/grid/voxelize) plus every voxel the outside cannot reach. Holes in the
// surface narrower than about 2 * closingVoxels voxels are closed first (morphological closing:
// the outside is flooded around the surface dilated by closingVoxels, then grown back by as
// much), so a mesh with small gaps still encloses its volume; larger openings (a basin's top)
// stay open.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/grid/normalization.h"
#include "core/grid/voxel_grid.h"

namespace sagrid {

struct Mesh;

namespace physics {

struct SolidVoxels {
  // The grid covers [-0.5, 0.5]^3 of `normalization`'s frame with a margin of at least one voxel
  // around the mesh, so the outside always reaches around it.
  Normalization normalization;
  VoxelGrid surface;
  VoxelGrid solid;  // surface voxels plus the enclosed inside
  std::size_t enclosedCount = 0;  // solid voxels that are not surface voxels
  // The outside reached voxels that the closing then gave back to the solid (holes closed).
  std::size_t closedCount = 0;
  double voxelSize() const { return 1.0 / (normalization.scale * surface.resolution()); }  // mesh units
};

// Throws Error for a mesh with no triangles or a box that cannot be normalized. `frame`, when
// given, is the box the grid spans (with the mesh's own bounds added): a body with parts cut away
// voxelizes on the same grid as the whole object.
SolidVoxels solidVoxels(const Mesh& mesh, int resolution, int closingVoxels,
                        const std::optional<Eigen::AlignedBox3f>& frame = std::nullopt);

}  // namespace physics
}  // namespace sagrid
