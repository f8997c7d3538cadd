#include "core/geometry/connected_parts.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "core/geometry/triangle_components.h"
#include "core/mesh/mesh.h"

namespace sagrid {

std::vector<ConnectedPart> connectedParts(const Mesh& mesh) {
  const TriangleComponents components = triangleComponents(mesh);
  std::vector<ConnectedPart> parts(static_cast<std::size_t>(components.count));
  std::vector<std::size_t> partOfVertex(components.weldedPositions.size(), SIZE_MAX);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int component = components.ofTriangle[t];
    if (component < 0) continue;
    ConnectedPart& part = parts[static_cast<std::size_t>(component)];
    const Eigen::Vector3f& a = mesh.positions[static_cast<std::size_t>(mesh.triangles[t][0])];
    const Eigen::Vector3f& b = mesh.positions[static_cast<std::size_t>(mesh.triangles[t][1])];
    const Eigen::Vector3f& c = mesh.positions[static_cast<std::size_t>(mesh.triangles[t][2])];
    part.triangles += 1;
    part.area += 0.5f * (b - a).cross(c - a).norm();
    for (int corner : components.weldedCorners[t])
      partOfVertex[static_cast<std::size_t>(corner)] = static_cast<std::size_t>(component);
  }
  const std::vector<Eigen::Vector3f>& distinct = components.weldedPositions;
  // Centroid, box and principal spread of each part's distinct vertices.
  std::vector<Eigen::Vector3d> sum(parts.size(), Eigen::Vector3d::Zero());
  std::vector<Eigen::Matrix3d> outer(parts.size(), Eigen::Matrix3d::Zero());
  std::vector<double> count(parts.size(), 0.0);
  for (std::size_t w = 0; w < distinct.size(); ++w) {
    if (partOfVertex[w] == SIZE_MAX) continue;
    const std::size_t p = partOfVertex[w];
    const Eigen::Vector3d x = distinct[w].cast<double>();
    sum[p] += x;
    outer[p] += x * x.transpose();
    count[p] += 1.0;
    parts[p].box.extend(distinct[w]);
  }
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Eigen::Vector3d mean = sum[p] / count[p];
    const Eigen::Matrix3d covariance = outer[p] / count[p] - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d values = solver.eigenvalues().cwiseMax(0.0);  // ascending
    parts[p].centroid = mean.cast<float>();
    parts[p].spread = Eigen::Vector3f(static_cast<float>(std::sqrt(values[2])),
                                      static_cast<float>(std::sqrt(values[1])),
                                      static_cast<float>(std::sqrt(values[0])));
  }
  std::stable_sort(parts.begin(), parts.end(), [](const ConnectedPart& a, const ConnectedPart& b) {
    return a.triangles > b.triangles;
  });
  return parts;
}

bool congruentParts(const ConnectedPart& a, const ConnectedPart& b, float tolerance) {
  if (a.triangles != b.triangles) return false;
  const float areaScale = std::max(a.area, b.area);
  if (std::abs(a.area - b.area) > tolerance * areaScale) return false;
  const float spreadScale = std::max(a.spread[0], b.spread[0]);
  return (a.spread - b.spread).cwiseAbs().maxCoeff() <= tolerance * spreadScale;
}

std::optional<float> similarityScale(const ConnectedPart& a, const ConnectedPart& b,
                                     float tolerance, float maxScale) {
  if (a.triangles != b.triangles || !(a.spread[0] > 0) || !(a.area > 0)) return std::nullopt;
  const float scale = b.spread[0] / a.spread[0];
  if (!(scale >= 1.0f / maxScale && scale <= maxScale)) return std::nullopt;
  const float area = scale * scale * a.area;
  if (std::abs(b.area - area) > tolerance * std::max(b.area, area)) return std::nullopt;
  const Eigen::Vector3f spread = scale * a.spread;
  if ((b.spread - spread).cwiseAbs().maxCoeff() > tolerance * b.spread[0]) return std::nullopt;
  return scale;
}

PartCopies::PartCopies(const std::vector<ConnectedPart>& parts, float tolerance, float maxScale)
    : m_parts(parts), m_tolerance(tolerance), m_maxScale(maxScale) {
  for (std::size_t p = 0; p < parts.size(); ++p)
    if (parts[p].triangles >= kMinInstanceTriangles) m_groups[parts[p].triangles].push_back(p);
}

std::vector<std::size_t> PartCopies::of(std::size_t p) const {
  std::vector<std::size_t> out;
  const auto group = m_groups.find(m_parts[p].triangles);
  if (group == m_groups.end()) return out;
  for (std::size_t q : group->second)
    if (q != p &&
        (congruentParts(m_parts[p], m_parts[q], m_tolerance) ||
         (m_maxScale > 1.0f && similarityScale(m_parts[p], m_parts[q], m_tolerance, m_maxScale))))
      out.push_back(q);
  return out;
}

std::vector<std::size_t> PartCopies::familyOf(std::size_t p) const {
  std::vector<std::size_t> family = of(p);
  family.push_back(p);
  return family;
}

float nearestCentroidDistance(std::size_t p, const std::vector<std::size_t>& family,
                              const std::vector<ConnectedPart>& parts) {
  float nearest = std::numeric_limits<float>::infinity();
  for (std::size_t q : family)
    if (q != p) nearest = std::min(nearest, (parts[p].centroid - parts[q].centroid).norm());
  return nearest;
}

bool isSmallPart(const ConnectedPart& part, float maxDiagonal) {
  return !part.box.isEmpty() && part.box.diagonal().norm() <= maxDiagonal;
}

bool isRoundFlatPart(const ConnectedPart& part) {
  const Eigen::Vector3f size = part.box.sizes();
  const float wide = std::max(size.x(), size.y()), narrow = std::min(size.x(), size.y());
  return wide > 0 && wide - narrow <= kRoundShare * wide && size.z() <= kFlatShare * narrow;
}

std::optional<std::size_t> partAt(const Eigen::Vector3f& point,
                                  const std::vector<ConnectedPart>& parts, float touch,
                                  float maxDiagonal) {
  std::optional<std::size_t> best;
  float bestGap = touch, bestDiagonal = 0.0f;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (!isSmallPart(parts[p], maxDiagonal)) continue;
    const float gap = parts[p].box.exteriorDistance(point);
    const float diagonal = parts[p].box.diagonal().norm();
    if (gap > bestGap || (best && gap == bestGap && diagonal >= bestDiagonal)) continue;
    best = p, bestGap = gap, bestDiagonal = diagonal;
  }
  return best;
}

}  // namespace sagrid
