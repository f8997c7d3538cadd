#include "core/geometry/triangle_components.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <unordered_map>

#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

// The same position (bit for bit: 0 and -0 apart, which a mesh's seams do not produce) and, split
// by material, the same material.
struct VertexKey {
  std::uint32_t x, y, z;
  int material;
  bool operator==(const VertexKey& o) const {
    return x == o.x && y == o.y && z == o.z && material == o.material;
  }
};
struct VertexKeyHash {
  std::size_t operator()(const VertexKey& k) const {
    std::uint64_t h = k.x;
    h = h * 0x9E3779B97F4A7C15ull ^ k.y;
    h = h * 0x9E3779B97F4A7C15ull ^ k.z;
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.material);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
VertexKey keyOf(const Eigen::Vector3f& p, int material) {
  VertexKey k{};
  std::memcpy(&k.x, &p.x(), sizeof(float));
  std::memcpy(&k.y, &p.y(), sizeof(float));
  std::memcpy(&k.z, &p.z(), sizeof(float));
  k.material = material;
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

TriangleComponents triangleComponents(const Mesh& mesh, bool splitByMaterial) {
  const std::size_t n = mesh.triangles.size();
  // Weld: one id per distinct (position, material) that a valid triangle uses.
  TriangleComponents result;
  std::unordered_map<VertexKey, int, VertexKeyHash> ids;
  std::vector<std::array<int, 3>>& corners = result.weldedCorners;
  corners.assign(n, {-1, -1, -1});
  std::vector<bool> valid(n);
  for (std::size_t t = 0; t < n; ++t) {
    valid[t] = validTriangle(mesh.triangles[t], mesh.positions.size());
    if (!valid[t]) continue;
    const int material = splitByMaterial && t < mesh.triangleMaterials.size()
                             ? mesh.triangleMaterials[t]
                             : -1;
    for (int c = 0; c < 3; ++c) {
      const auto& p = mesh.positions[static_cast<std::size_t>(mesh.triangles[t][c])];
      const auto [it, added] = ids.emplace(keyOf(p, material), static_cast<int>(ids.size()));
      if (added) result.weldedPositions.push_back(p);
      corners[t][c] = it->second;
    }
  }
  UnionFind sets(ids.size());
  for (std::size_t t = 0; t < n; ++t) {
    if (!valid[t]) continue;
    const auto& c = corners[t];
    sets.join(static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[1]));
    sets.join(static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[2]));
  }
  result.ofTriangle.assign(n, -1);
  std::unordered_map<std::size_t, int> componentOfRoot;
  for (std::size_t t = 0; t < n; ++t) {
    if (!valid[t]) continue;
    const auto [it, added] = componentOfRoot.emplace(sets.find(static_cast<std::size_t>(corners[t][0])), result.count);
    if (added) ++result.count;
    result.ofTriangle[t] = it->second;
  }
  return result;
}

}  // namespace sagrid
