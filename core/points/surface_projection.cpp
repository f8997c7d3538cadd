#include "core/points/surface_projection.h"

#include "core/geometry/surface_scene.h"

namespace sagrid {

SurfacePoint projectToSurface(const Eigen::Vector3f& normalizedPoint,
                              const Normalization& normalization, const SurfaceScene& scene,
                              UpAxis fileUp) {
  const Eigen::Vector3f meshPoint = normalization.toMesh(normalizedPoint);
  const ClosestPoint closest = scene.closestPoint(meshPoint);
  SurfacePoint p;
  p.position = zUpToFile(closest.position, fileUp);
  p.normal = zUpToFile(closest.normal, fileUp).normalized();
  p.moved = closest.distance;
  return p;
}

}  // namespace sagrid
