// The point of a triangle closest to a query point (Ericson, Real-Time Collision Detection,
// 5.1.5): Voronoi-region tests, no square roots; degenerate triangles fall back to edges.
#pragma once

#include <Eigen/Core>

namespace sagrid {

Eigen::Vector3f closestPointOnTriangle(const Eigen::Vector3f& p, const Eigen::Vector3f& a,
                                       const Eigen::Vector3f& b, const Eigen::Vector3f& c);

}  // namespace sagrid
