#include "core/features/surface_samples.h"

#include <algorithm>
#include <cmath>

#include "core/mesh/mesh.h"

namespace sagrid {

namespace {
// Convex polygon, at most 3 + 6 vertices after clipping a triangle by a box.
struct Polygon {
  Eigen::Vector3f v[12];
  int n = 0;
};

// Keeps the part with lo <= p[axis] <= hi (Sutherland-Hodgman, two planes).
Polygon clip(const Polygon& in, int axis, float lo, float hi) {
  Polygon a;
  for (int i = 0; i < in.n; ++i) {
    const Eigen::Vector3f& p = in.v[i];
    const Eigen::Vector3f& q = in.v[(i + 1) % in.n];
    const bool pIn = p[axis] >= lo, qIn = q[axis] >= lo;
    if (pIn) a.v[a.n++] = p;
    if (pIn != qIn) a.v[a.n++] = p + (q - p) * ((lo - p[axis]) / (q[axis] - p[axis]));
  }
  Polygon b;
  for (int i = 0; i < a.n; ++i) {
    const Eigen::Vector3f& p = a.v[i];
    const Eigen::Vector3f& q = a.v[(i + 1) % a.n];
    const bool pIn = p[axis] <= hi, qIn = q[axis] <= hi;
    if (pIn) b.v[b.n++] = p;
    if (pIn != qIn) b.v[b.n++] = p + (q - p) * ((hi - p[axis]) / (q[axis] - p[axis]));
  }
  return b;
}

std::pair<int, int> cellRange(const Polygon& poly, int axis, int res) {
  float lo = poly.v[0][axis], hi = lo;
  for (int i = 1; i < poly.n; ++i) {
    lo = std::min(lo, poly.v[i][axis]);
    hi = std::max(hi, poly.v[i][axis]);
  }
  const int first = std::max(0, static_cast<int>(std::floor((lo + 0.5f) * res)));
  const int last = std::min(res - 1, static_cast<int>(std::floor((hi + 0.5f) * res)));
  return {first, last};
}
}  // namespace

std::vector<int> occupiedSlots(const VoxelGrid& grid) {
  std::vector<int> slots(grid.voxelCount(), -1);
  int next = 0;
  const auto& occ = grid.occupancy();
  for (std::size_t i = 0; i < occ.size(); ++i) {
    if (occ[i]) slots[i] = next++;
  }
  return slots;
}

void forEachSurfacePiece(const Mesh& mesh, const VoxelGrid& grid,
                         const std::function<void(const SurfacePiece&)>& visit) {
  const std::vector<int> slots = occupiedSlots(grid);
  const int res = grid.resolution();
  const float h = 1.0f / res;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3f& a = mesh.positions[tri[0]];
    const Eigen::Vector3f ab = mesh.positions[tri[1]] - a, ac = mesh.positions[tri[2]] - a;
    const Eigen::Vector3f cross = ab.cross(ac);
    const float twiceArea = cross.norm();
    if (!(twiceArea > 0.0f)) continue;  // degenerate (or NaN) triangles carry no surface
    const Eigen::Vector3f n = cross / twiceArea;
    Polygon whole;
    whole.v[0] = a;
    whole.v[1] = a + ab;
    whole.v[2] = a + ac;
    whole.n = 3;
    const auto [i0, i1] = cellRange(whole, 0, res);
    for (int i = i0; i <= i1; ++i) {
      const Polygon px = clip(whole, 0, i * h - 0.5f, (i + 1) * h - 0.5f);
      if (px.n < 3) continue;
      const auto [j0, j1] = cellRange(px, 1, res);
      for (int j = j0; j <= j1; ++j) {
        const Polygon py = clip(px, 1, j * h - 0.5f, (j + 1) * h - 0.5f);
        if (py.n < 3) continue;
        const auto [k0, k1] = cellRange(py, 2, res);
        for (int k = k0; k <= k1; ++k) {
          const Polygon pz = clip(py, 2, k * h - 0.5f, (k + 1) * h - 0.5f);
          if (pz.n < 3) continue;
          const int slot = slots[grid.linearIndex({i, j, k})];
          if (slot < 0) continue;  // touches the voxel only on its boundary
          Eigen::Vector3f areaVec = Eigen::Vector3f::Zero();
          for (int m = 0; m < pz.n; ++m) areaVec += pz.v[m].cross(pz.v[(m + 1) % pz.n]);
          const float area = 0.5f * std::abs(areaVec.dot(n));
          if (area <= 0.0f) continue;
          visit({static_cast<int>(t), slot, pz.v, pz.n, area, n});
        }
      }
    }
  }
}

Eigen::Vector2f barycentricIn(const Mesh& mesh, int triangle, const Eigen::Vector3f& p) {
  const Eigen::Vector3i& tri = mesh.triangles[static_cast<std::size_t>(triangle)];
  const Eigen::Vector3f& a = mesh.positions[tri[0]];
  const Eigen::Vector3f ab = mesh.positions[tri[1]] - a, ac = mesh.positions[tri[2]] - a;
  const Eigen::Vector3f cross = ab.cross(ac);
  const float twiceArea = cross.norm();
  const float twiceAreaSquared = twiceArea * twiceArea;
  const Eigen::Vector3f d = p - a;
  return {d.cross(ac).dot(cross) / twiceAreaSquared, ab.cross(d).dot(cross) / twiceAreaSquared};
}

std::vector<VoxelSurfaceStats> voxelSurfaceStats(const Mesh& mesh, const VoxelGrid& grid) {
  std::vector<VoxelSurfaceStats> stats(grid.occupiedCount());
  forEachSurfacePiece(mesh, grid, [&](const SurfacePiece& piece) {
    Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
    for (int m = 0; m < piece.vertexCount; ++m) centroid += piece.vertices[m];
    centroid /= static_cast<float>(piece.vertexCount);
    const Eigen::Vector2f uv = barycentricIn(mesh, piece.triangle, centroid);
    const Eigen::Vector3f albedo = mesh.albedo(piece.triangle, uv.x(), uv.y());
    const Eigen::Vector3f& n = piece.normal;
    const std::array<float, 6> nn{n.x() * n.x(), n.y() * n.y(), n.z() * n.z(),
                                  n.x() * n.y(), n.x() * n.z(), n.y() * n.z()};
    VoxelSurfaceStats& st = stats[static_cast<std::size_t>(piece.slot)];
    st.area += piece.area;
    for (int c = 0; c < 3; ++c) st.albedo[c] += piece.area * albedo[c];
    for (int c = 0; c < 6; ++c) st.normalTensor[c] += piece.area * nn[c];
  });
  return stats;
}

}  // namespace sagrid
