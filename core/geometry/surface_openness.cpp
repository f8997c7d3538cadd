#include "core/geometry/surface_openness.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/geometry/surface_scene.h"

namespace sagrid {

namespace {

// Directions spread evenly over the sphere (a Fibonacci lattice): half of them fall on each side
// of any surface.
constexpr int kDirections = 64;

const std::vector<Eigen::Vector3f>& sphereDirections() {
  static const std::vector<Eigen::Vector3f> directions = [] {
    std::vector<Eigen::Vector3f> d;
    const float golden = static_cast<float>(M_PI) * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < kDirections; ++i) {
      const float z = 1.0f - (2.0f * i + 1.0f) / kDirections;
      const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
      d.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return d;
  }();
  return directions;
}

float freeDistance(const SurfaceScene& scene, const Eigen::Vector3f& origin,
                   const Eigen::Vector3f& direction) {
  const auto hit = scene.intersect(origin, direction);
  return hit ? hit->distance : std::numeric_limits<float>::infinity();
}

}  // namespace

SurfaceOpenness surfaceOpenness(const SurfaceScene& scene, const ClosestPoint& at, float offset) {
  SurfaceOpenness open;
  Eigen::Vector3f outside = at.position;
  float mostOpen = -1;
  for (const float side : {1.0f, -1.0f}) {
    const Eigen::Vector3f normal = side * at.normal;
    const Eigen::Vector3f origin = at.position + offset * normal;
    int facing = 0, leaving = 0;
    for (const Eigen::Vector3f& d : sphereDirections()) {
      if (d.dot(normal) <= 0) continue;
      ++facing;
      leaving += !scene.occluded(origin, d, 0.0f, std::numeric_limits<float>::infinity());
    }
    const float openness = facing ? static_cast<float>(leaving) / facing : 0.0f;
    if (openness <= mostOpen) continue;  // a tie: the side the triangle faces, tried first
    mostOpen = openness;
    outside = origin;
  }
  open.openness = mostOpen;
  open.below = freeDistance(scene, outside, -Eigen::Vector3f::UnitZ());
  open.above = freeDistance(scene, outside, Eigen::Vector3f::UnitZ());
  return open;
}

}  // namespace sagrid
