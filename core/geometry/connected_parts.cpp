#include "core/geometry/connected_parts.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

// The same position, bit for bit (0 and -0 apart, which a mesh's seams do not produce).
struct PositionKey {
  std::uint32_t x, y, z;
  bool operator==(const PositionKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PositionKeyHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = k.x;
    h = h * 0x9E3779B97F4A7C15ull ^ k.y;
    h = h * 0x9E3779B97F4A7C15ull ^ k.z;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
PositionKey keyOf(const Eigen::Vector3f& p) {
  PositionKey k{};
  std::memcpy(&k.x, &p.x(), sizeof(float));
  std::memcpy(&k.y, &p.y(), sizeof(float));
  std::memcpy(&k.z, &p.z(), sizeof(float));
  return k;
}

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : m_parent(n) {
    std::iota(m_parent.begin(), m_parent.end(), std::size_t{0});
  }
  std::size_t find(std::size_t a) {
    while (m_parent[a] != a) a = m_parent[a] = m_parent[m_parent[a]];
    return a;
  }
  void join(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) m_parent[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> m_parent;
};

bool validTriangle(const Eigen::Vector3i& t, std::size_t vertices) {
  for (int c = 0; c < 3; ++c)
    if (t[c] < 0 || static_cast<std::size_t>(t[c]) >= vertices) return false;
  return true;
}

}  // namespace

std::vector<ConnectedPart> connectedParts(const Mesh& mesh) {
  // Weld: one id per distinct position.
  std::unordered_map<PositionKey, std::size_t, PositionKeyHash> ids;
  std::vector<std::size_t> welded(mesh.positions.size());
  std::vector<Eigen::Vector3f> distinct;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const auto [it, added] = ids.emplace(keyOf(mesh.positions[v]), distinct.size());
    if (added) distinct.push_back(mesh.positions[v]);
    welded[v] = it->second;
  }
  UnionFind sets(distinct.size());
  for (const auto& t : mesh.triangles) {
    if (!validTriangle(t, mesh.positions.size())) continue;
    sets.join(welded[static_cast<std::size_t>(t[0])], welded[static_cast<std::size_t>(t[1])]);
    sets.join(welded[static_cast<std::size_t>(t[0])], welded[static_cast<std::size_t>(t[2])]);
  }
  // One part per root that a triangle reaches, in the order of the first triangle.
  std::unordered_map<std::size_t, std::size_t> partOfRoot;
  std::vector<ConnectedPart> parts;
  std::vector<std::size_t> partOfVertex(distinct.size(), SIZE_MAX);
  for (const auto& t : mesh.triangles) {
    if (!validTriangle(t, mesh.positions.size())) continue;
    const std::size_t root = sets.find(welded[static_cast<std::size_t>(t[0])]);
    const auto [it, added] = partOfRoot.emplace(root, parts.size());
    if (added) parts.emplace_back();
    ConnectedPart& part = parts[it->second];
    const Eigen::Vector3f& a = mesh.positions[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3f& b = mesh.positions[static_cast<std::size_t>(t[1])];
    const Eigen::Vector3f& c = mesh.positions[static_cast<std::size_t>(t[2])];
    part.triangles += 1;
    part.area += 0.5f * (b - a).cross(c - a).norm();
    for (int corner = 0; corner < 3; ++corner) {
      const std::size_t w = welded[static_cast<std::size_t>(t[corner])];
      partOfVertex[w] = it->second;
    }
  }
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
