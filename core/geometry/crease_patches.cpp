#include "core/geometry/crease_patches.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "core/geometry/material_parts.h"
#include "core/geometry/triangle_components.h"
#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

// The patch a triangle belongs to (union-find with path halving).
int rootOf(std::vector<int>& parent, int t) {
  while (parent[static_cast<std::size_t>(t)] != t) {
    int& up = parent[static_cast<std::size_t>(t)];
    up = parent[static_cast<std::size_t>(up)];
    t = up;
  }
  return t;
}

}  // namespace

std::vector<ConnectedPart> creasePatches(const Mesh& mesh, float creaseDegrees) {
  const TriangleComponents components = triangleComponents(mesh);
  const std::size_t n = mesh.triangles.size();
  std::vector<Eigen::Vector3f> normal(n, Eigen::Vector3f::Zero());
  for (std::size_t t = 0; t < n; ++t) {
    if (components.ofTriangle[t] < 0) continue;
    const auto& c = mesh.triangles[t];
    const Eigen::Vector3f& a = mesh.positions[static_cast<std::size_t>(c[0])];
    const Eigen::Vector3f face = (mesh.positions[static_cast<std::size_t>(c[1])] - a)
                                     .cross(mesh.positions[static_cast<std::size_t>(c[2])] - a);
    if (face.norm() > 0 && face.allFinite()) normal[t] = face.normalized();
  }
  const float smooth = std::cos(creaseDegrees * static_cast<float>(M_PI) / 180.0f);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  // Each welded edge's first triangle; later triangles on it join it where the turn is smooth.
  std::unordered_map<std::uint64_t, std::vector<int>> onEdge;
  for (std::size_t t = 0; t < n; ++t) {
    if (components.ofTriangle[t] < 0 || normal[t].isZero()) continue;
    const auto& w = components.weldedCorners[t];
    for (int e = 0; e < 3; ++e) {
      const auto lo = static_cast<std::uint32_t>(std::min(w[e], w[(e + 1) % 3]));
      const auto hi = static_cast<std::uint32_t>(std::max(w[e], w[(e + 1) % 3]));
      if (lo == hi) continue;
      auto& others = onEdge[(static_cast<std::uint64_t>(lo) << 32) | hi];
      for (int o : others)
        if (std::abs(normal[t].dot(normal[static_cast<std::size_t>(o)])) >= smooth)
          parent[static_cast<std::size_t>(rootOf(parent, static_cast<int>(t)))] = rootOf(parent, o);
      others.push_back(static_cast<int>(t));
    }
  }
  std::vector<int> patch(n);
  for (std::size_t t = 0; t < n; ++t) patch[t] = rootOf(parent, static_cast<int>(t));
  std::vector<ConnectedPart> out;
  for (auto& group : groupParts(mesh, patch)) out.push_back(std::move(group.part));
  std::stable_sort(out.begin(), out.end(), [](const ConnectedPart& a, const ConnectedPart& b) {
    return a.triangles > b.triangles;
  });
  return out;
}

}  // namespace sagrid
