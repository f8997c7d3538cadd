// Points covering the surface of a triangle set at a given spacing: each triangle is halved
// across its longest edge until every edge is at most `spacing`; the corners, the midpoints made
// on the way and the final pieces' centroids are the samples. Used to measure how far a hull's
// surface strays from a mesh. A template so that the per-sample call inlines (it runs millions
// of times per decomposition).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include <Eigen/Core>

namespace sagrid::physics {

template <typename Sample>
void sampleTriangles(const std::vector<Eigen::Vector3f>& vertices,
                     const std::vector<Eigen::Vector3i>& triangles, float spacing, Sample&& sample) {
  const float limit = spacing * spacing;
  std::vector<std::array<Eigen::Vector3f, 3>> stack;
  for (const auto& t : triangles) {
    for (int c = 0; c < 3; ++c) sample(vertices[t[c]]);
    stack.push_back({vertices[t[0]], vertices[t[1]], vertices[t[2]]});
    while (!stack.empty()) {
      const auto [a, b, c] = stack.back();
      stack.pop_back();
      const float ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
      if (std::max({ab, bc, ca}) <= limit) {
        sample((a + b + c) / 3.0f);
        continue;
      }
      if (ab >= bc && ab >= ca) {
        const Eigen::Vector3f m = 0.5f * (a + b);
        sample(m);
        stack.push_back({a, m, c});
        stack.push_back({m, b, c});
      } else if (bc >= ca) {
        const Eigen::Vector3f m = 0.5f * (b + c);
        sample(m);
        stack.push_back({a, b, m});
        stack.push_back({a, m, c});
      } else {
        const Eigen::Vector3f m = 0.5f * (c + a);
        sample(m);
        stack.push_back({a, b, m});
        stack.push_back({m, b, c});
      }
    }
  }
}

}  // namespace sagrid::physics
