#include "core/generate/generated_object.h"

#include "core/geometry/closest_point_on_triangle.h"

#include <cmath>
#include <limits>

namespace sagrid::gen {

namespace {
Eigen::Vector3f closestOnRange(const Mesh& mesh, const Eigen::Vector3f& p, std::size_t begin,
                               std::size_t end, float& bestDistance) {
  Eigen::Vector3f best = p;
  bestDistance = std::numeric_limits<float>::infinity();
  for (std::size_t t = begin; t < end && t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3f q =
        closestPointOnTriangle(p, mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]);
    const float d = (q - p).norm();
    if (d < bestDistance) {
      bestDistance = d;
      best = q;
    }
  }
  return best;
}
}  // namespace

GeneratedObject makeGeneratedObject(std::string category, Mesh mesh,
                                    std::vector<GroundTruthPoint> points, nlohmann::json params) {
  GeneratedObject out;
  out.category = std::move(category);
  out.mesh = std::move(mesh);
  out.points = std::move(points);
  out.generator = std::move(params);
  return out;
}

float roundedToMillimetre(float metres) { return std::round(metres * 1000.0f) / 1000.0f; }

void keepPointsNearParts(const Mesh& mesh, std::vector<GroundTruthPoint>& points, float maxDistance) {
  for (auto& point : points) {
    float d = 0;
    const Eigen::Vector3f q =
        closestOnRange(mesh, point.position, point.triangleBegin, point.triangleEnd, d);
    if (d > maxDistance && std::isfinite(d)) {
      point.position = q + (point.position - q) * (maxDistance / d);
    }
  }
}

}  // namespace sagrid::gen
