#include "core/generate/generated_object.h"

#include <cmath>
#include <limits>

namespace sagrid::gen {

Eigen::Vector3f closestPointOnTriangle(const Eigen::Vector3f& p, const Eigen::Vector3f& a,
                                       const Eigen::Vector3f& b, const Eigen::Vector3f& c) {
  const Eigen::Vector3f ab = b - a, ac = c - a, ap = p - a;
  const float d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3f bp = p - b;
  const float d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Eigen::Vector3f cp = p - c;
  const float d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const float denom = 1.0f / (va + vb + vc);
  if (!(denom == denom) || std::abs(va + vb + vc) < 1e-30f) return a;  // degenerate triangle
  return a + ab * (vb * denom) + ac * (vc * denom);
}

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

float distanceToMesh(const Mesh& mesh, const Eigen::Vector3f& p) {
  float d = 0;
  closestOnRange(mesh, p, 0, mesh.triangles.size(), d);
  return d;
}

}  // namespace sagrid::gen
