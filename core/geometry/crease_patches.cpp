#include "core/geometry/crease_patches.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>

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
  // The triangles met so far on each welded edge, in the order met: a list threaded through one
  // array of (triangle, next) entries, the map holding each edge's first and last entry (no
  // allocation per edge). A triangle joins each earlier one on its edges where the turn is smooth.
  struct Entry {
    int triangle, next;
  };
  std::vector<Entry> entries;
  entries.reserve(3 * n);
  std::unordered_map<std::uint64_t, std::pair<int, int>> onEdge;  // first, last entry
  onEdge.reserve(3 * n / 2);
  for (std::size_t t = 0; t < n; ++t) {
    if (components.ofTriangle[t] < 0 || normal[t].isZero()) continue;
    const auto& w = components.weldedCorners[t];
    for (int e = 0; e < 3; ++e) {
      const auto lo = static_cast<std::uint32_t>(std::min(w[e], w[(e + 1) % 3]));
      const auto hi = static_cast<std::uint32_t>(std::max(w[e], w[(e + 1) % 3]));
      if (lo == hi) continue;
      const int entry = static_cast<int>(entries.size());
      entries.push_back({static_cast<int>(t), -1});
      const auto [at, isNew] =
          onEdge.try_emplace((static_cast<std::uint64_t>(lo) << 32) | hi, entry, entry);
      if (isNew) continue;
      for (int i = at->second.first; i >= 0; i = entries[static_cast<std::size_t>(i)].next) {
        const int o = entries[static_cast<std::size_t>(i)].triangle;
        if (std::abs(normal[t].dot(normal[static_cast<std::size_t>(o)])) >= smooth)
          parent[static_cast<std::size_t>(rootOf(parent, static_cast<int>(t)))] = rootOf(parent, o);
      }
      entries[static_cast<std::size_t>(at->second.second)].next = entry;
      at->second.second = entry;
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
