#include "analytic_meshes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/closest_point_on_triangle.h"

namespace sagrid::test {

Mesh uvSphere(const Eigen::Vector3f& centre, float radius, int rings) {
  Mesh mesh;
  const int segments = 2 * rings;
  for (int r = 0; r <= rings; ++r) {
    const float theta = static_cast<float>(M_PI) * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * static_cast<float>(M_PI) * s / segments;
      const Eigen::Vector3f n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
      mesh.positions.push_back(centre + radius * n);
      mesh.normals.push_back(n);
    }
  }
  const int row = segments + 1;
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const int a = r * row + s, b = a + 1, c = a + row, d = c + 1;
      if (r > 0) mesh.triangles.emplace_back(a, c, b);
      if (r < rings - 1) mesh.triangles.emplace_back(b, c, d);
    }
  }
  return mesh;
}

Mesh box(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.positions.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                                i & 4 ? hi.z() : lo.z());
  }
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    mesh.triangles.emplace_back(f[0], f[1], f[2]);
    mesh.triangles.emplace_back(f[0], f[2], f[3]);
  }
  mesh.computeVertexNormals();
  return mesh;
}

Mesh cylinder(float radius, float height, int segments, const Eigen::Matrix3f& turn,
              const Eigen::Vector3f& offset) {
  Mesh m;
  for (int k = 0; k < 2; ++k) {
    for (int i = 0; i < segments; ++i) {
      const float phi = 2.0f * static_cast<float>(M_PI) * static_cast<float>(i) / static_cast<float>(segments);
      m.positions.push_back(turn * Eigen::Vector3f(radius * std::cos(phi), radius * std::sin(phi),
                                                   static_cast<float>(k) * height) + offset);
    }
  }
  const int centre = static_cast<int>(m.positions.size());
  m.positions.push_back(offset);
  m.positions.push_back(turn * Eigen::Vector3f(0, 0, height) + offset);
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    m.triangles.emplace_back(i, j, segments + j);
    m.triangles.emplace_back(i, segments + j, segments + i);
    m.triangles.emplace_back(centre, j, i);
    m.triangles.emplace_back(centre + 1, segments + i, segments + j);
  }
  m.computeVertexNormals();
  return m;
}

Mesh quadZ(const Eigen::Vector2f& lo, const Eigen::Vector2f& hi, float z) {
  Mesh mesh;
  mesh.positions = {
      {lo.x(), lo.y(), z}, {hi.x(), lo.y(), z}, {hi.x(), hi.y(), z}, {lo.x(), hi.y(), z}};
  mesh.normals.assign(4, Eigen::Vector3f::UnitZ());
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

Mesh plateWithPlateaus(int cellsX, int cellsY, float rise,
                       const std::vector<std::array<int, 4>>& plateaus) {
  Mesh mesh;
  for (int j = 0; j <= cellsY; ++j)
    for (int i = 0; i <= cellsX; ++i) {
      bool raised = false;
      for (const auto& p : plateaus) raised |= i >= p[0] && i <= p[1] && j >= p[2] && j <= p[3];
      mesh.positions.emplace_back(0.1f * i, 0.1f * j, raised ? rise : 0.0f);
    }
  const auto at = [&](int i, int j) { return j * (cellsX + 1) + i; };
  for (int j = 0; j < cellsY; ++j)
    for (int i = 0; i < cellsX; ++i) {
      mesh.triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  mesh.computeVertexNormals();
  return mesh;
}

void append(Mesh& a, const Mesh& b) {
  const int offset = static_cast<int>(a.positions.size());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
  if (!a.colors.empty() || !b.colors.empty()) {
    a.colors.resize(offset, Eigen::Vector3f::Ones());
    if (b.colors.empty()) {
      a.colors.resize(a.positions.size(), Eigen::Vector3f::Ones());
    } else {
      a.colors.insert(a.colors.end(), b.colors.begin(), b.colors.end());
    }
  }
  for (const auto& t : b.triangles) a.triangles.push_back(t + Eigen::Vector3i::Constant(offset));
}

void paint(Mesh& mesh, const Eigen::Vector3f& rgb) {
  mesh.colors.assign(mesh.positions.size(), rgb);
}

float bruteForceDistance(const Mesh& mesh, const Eigen::Vector3f& p) {
  float best = std::numeric_limits<float>::infinity();
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3f q = closestPointOnTriangle(p, mesh.positions[t[0]], mesh.positions[t[1]],
                                                     mesh.positions[t[2]]);
    best = std::min(best, (q - p).norm());
  }
  return best;
}

}  // namespace sagrid::test
