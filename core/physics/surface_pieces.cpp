#include "core/physics/surface_pieces.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/mesh/mesh.h"

namespace sagrid::physics {

namespace {

using Polygon = std::vector<Eigen::Vector3d>;

constexpr int kDirections = 14;

const std::array<Eigen::Vector3d, kDirections>& directions() {
  static const std::array<Eigen::Vector3d, kDirections> all = [] {
    std::array<Eigen::Vector3d, kDirections> d;
    int n = 0;
    for (int axis = 0; axis < 3; ++axis) {
      d[n++] = Eigen::Vector3d::Unit(axis);
      d[n++] = -Eigen::Vector3d::Unit(axis);
    }
    for (int sx = -1; sx <= 1; sx += 2)
      for (int sy = -1; sy <= 1; sy += 2)
        for (int sz = -1; sz <= 1; sz += 2) d[n++] = Eigen::Vector3d(sx, sy, sz);
    return d;
  }();
  return all;
}

// Splits a convex polygon by the plane x[axis] = c into the parts below and above.
void splitPolygon(const Polygon& polygon, int axis, double c, Polygon& below, Polygon& above) {
  below.clear();
  above.clear();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % n];
    const double da = a[axis] - c, db = b[axis] - c;
    if (da <= 0) below.push_back(a);
    if (da >= 0) above.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      Eigen::Vector3d p = a + (b - a) * (da / (da - db));
      p[axis] = c;  // exactly on the voxel face
      below.push_back(p);
      above.push_back(p);
    }
  }
}

struct Extremes {
  std::array<double, kDirections> reach;
  std::array<Eigen::Vector3f, kDirections> point;
  Extremes() { reach.fill(-1e300); }
  void add(const Eigen::Vector3d& p) {
    for (int d = 0; d < kDirections; ++d) {
      const double r = directions()[d].dot(p);
      if (r > reach[d]) reach[d] = r, point[d] = p.cast<float>();
    }
  }
};

}  // namespace

SurfacePieces::SurfacePieces(const Mesh& mesh, const Normalization& normalization, int resolution)
    : m_slot(static_cast<std::size_t>(resolution) * resolution * resolution, -1) {
  const int n = resolution;
  std::vector<Extremes> extremes;
  auto toGrid = [&](const Eigen::Vector3f& p) {
    return Eigen::Vector3d((normalization.toNormalized(p).cast<double>().array() + 0.5) * n);
  };
  // Cuts a polygon along `axis` into unit slabs and hands each piece with its slab index on.
  auto slabs = [n](const Polygon& polygon, int axis, auto&& each) {
    double lo = 1e300, hi = -1e300;
    for (const auto& p : polygon) lo = std::min(lo, p[axis]), hi = std::max(hi, p[axis]);
    const int first = std::max(0, static_cast<int>(std::floor(lo)));
    const int last = std::min(n - 1, static_cast<int>(std::floor(hi)));
    if (first > last) return;
    if (first == last) {
      each(polygon, first);
      return;
    }
    Polygon rest = polygon, below, above;
    for (int c = first; c <= last && !rest.empty(); ++c) {
      if (c == last) {
        each(rest, c);
        break;
      }
      splitPolygon(rest, axis, c + 1.0, below, above);
      if (below.size() >= 1) each(below, c);
      rest.swap(above);
    }
  };
  for (const Eigen::Vector3i& tri : mesh.triangles) {
    Polygon triangle{toGrid(mesh.positions[tri[0]]), toGrid(mesh.positions[tri[1]]),
                     toGrid(mesh.positions[tri[2]])};
    if (!triangle[0].allFinite() || !triangle[1].allFinite() || !triangle[2].allFinite()) continue;
    slabs(triangle, 0, [&](const Polygon& px, int i) {
      slabs(px, 1, [&](const Polygon& py, int j) {
        slabs(py, 2, [&](const Polygon& pz, int k) {
          const std::size_t voxel = (static_cast<std::size_t>(i) * n + j) * n + k;
          if (m_slot[voxel] < 0) {
            m_slot[voxel] = static_cast<std::int32_t>(extremes.size());
            extremes.emplace_back();
          }
          Extremes& e = extremes[m_slot[voxel]];
          for (const auto& p : pz) e.add(p);
        });
      });
    });
  }
  m_points.resize(extremes.size());
  for (std::size_t s = 0; s < extremes.size(); ++s) {
    auto& points = m_points[s];
    for (const auto& p : extremes[s].point)
      if (std::find(points.begin(), points.end(), p) == points.end()) points.push_back(p);
  }
}

const std::vector<Eigen::Vector3f>& SurfacePieces::points(std::size_t voxel) const {
  static const std::vector<Eigen::Vector3f> kNone;
  return m_slot[voxel] < 0 ? kNone : m_points[m_slot[voxel]];
}

}  // namespace sagrid::physics
