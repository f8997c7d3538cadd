#include "core/geometry/closest_point_on_triangle.h"

#include <algorithm>

namespace sagrid {

namespace {
Eigen::Vector3f closestOnSegment(const Eigen::Vector3f& p, const Eigen::Vector3f& a,
                                 const Eigen::Vector3f& b) {
  const Eigen::Vector3f ab = b - a;
  const float len2 = ab.squaredNorm();
  if (!(len2 > 0)) return a;
  const float t = std::clamp((p - a).dot(ab) / len2, 0.0f, 1.0f);
  return a + t * ab;
}
}  // namespace

Eigen::Vector3f closestPointOnTriangle(const Eigen::Vector3f& p, const Eigen::Vector3f& a,
                                       const Eigen::Vector3f& b, const Eigen::Vector3f& c) {
  const Eigen::Vector3f ab = b - a, ac = c - a, ap = p - a;
  const float d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;

  const Eigen::Vector3f bp = p - b;
  const float d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;

  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;

  const Eigen::Vector3f cp = p - c;
  const float d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;

  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;

  const float va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }

  const float sum = va + vb + vc;
  if (!(sum > 0)) {
    // Degenerate (zero-area) triangle: the closest of its three edges.
    const Eigen::Vector3f candidates[3] = {closestOnSegment(p, a, b), closestOnSegment(p, b, c),
                                           closestOnSegment(p, c, a)};
    return *std::min_element(std::begin(candidates), std::end(candidates),
                             [&](const auto& x, const auto& y) {
                               return (x - p).squaredNorm() < (y - p).squaredNorm();
                             });
  }
  const float v = vb / sum, w = vc / sum;
  return a + v * ab + w * ac;
}

}  // namespace sagrid
