// Mapping a predicted point back to the mesh file's frame and onto the surface (paper, III-D:
// "mapped back to the original object coordinates and projected onto the collision mesh
// surface"): normalized frame -> mesh frame (z up) -> closest surface point (Embree) -> the file's
// own up axis, with the surface normal there.
#pragma once

#include <Eigen/Core>

#include "core/grid/normalization.h"
#include "core/mesh/mesh.h"

namespace sagrid {

class SurfaceScene;

struct SurfacePoint {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();  // mesh file coordinates
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();   // unit, mesh file frame
  float moved = 0;  // distance from the unprojected point to the surface (mesh units)
};

// `scene` must be built from the z-up mesh that `normalization` belongs to.
SurfacePoint projectToSurface(const Eigen::Vector3f& normalizedPoint,
                              const Normalization& normalization, const SurfaceScene& scene,
                              UpAxis fileUp);

}  // namespace sagrid
