// A convex collision part as simulators take it (MuJoCo mesh geoms, URDF collision meshes): the
// vertices and outward-facing triangles of one convex hull, in the frame and units of the mesh it
// was computed from. Every part made by this module has >= 4 vertices and a volume > 0.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

namespace sagrid {

struct Mesh;

namespace physics {

struct ConvexPart {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from outside

  double volume() const;
  Eigen::Vector3d centroid() const;  // of the solid
  // True when point p is inside or within `tolerance` of the part.
  bool contains(const Eigen::Vector3f& p, float tolerance = 0.0f) const;
};

// The convex hull of `points` with at most `maxVertices` vertices (0: no limit; the hull is then
// grown greedily from the farthest points, so it may leave out points a little inside its true
// hull). Flat or collinear point sets are thickened to `minThickness` around their plane (a thin
// box for a plane); nullopt when the points span no extent at all (fewer than 2 distinct points)
// or minThickness is 0 for a flat set.
std::optional<ConvexPart> convexHull(const std::vector<Eigen::Vector3f>& points,
                                     int maxVertices = 0, float minThickness = 0.0f);

// A part as a Mesh (positions, triangles, flat vertex normals left empty), for writing with the
// mesh exporters or drawing.
Mesh toMesh(const ConvexPart& part);

}  // namespace physics
}  // namespace sagrid
