#include "core/grid/voxelize.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

using Vec3 = Eigen::Vector3d;

// Triangle-box overlap by the separating axis theorem (Akenine-Moeller 2001), in grid units where
// voxel (i,j,k) is the closed cube [i,i+1]x[j,j+1]x[k,k+1] (half-size 0.5). The three box-normal
// axes are covered by only visiting voxels that the triangle's bounding box touches; the plane
// and the nine edge-cross-axis tests are precomputed per triangle so that each candidate voxel
// costs a few multiply-adds. Comparisons are closed (touching counts as overlap), and the work
// is in double so that meshes with dyadic coordinates (the tests' analytic meshes) are exact.
struct TriangleTests {
  Vec3 normal;
  double planeOffset;  // normal . v0
  double planeRadius;  // projection radius of the voxel on the normal
  struct Axis {
    Vec3 direction;
    double minProjection, maxProjection, radius;
  };
  std::array<Axis, 9> axes;
  int axisCount = 0;

  TriangleTests(const Vec3& v0, const Vec3& v1, const Vec3& v2) {
    const std::array<Vec3, 3> edges{v1 - v0, v2 - v1, v0 - v2};
    normal = edges[0].cross(edges[1]);
    planeOffset = normal.dot(v0);
    planeRadius = 0.5 * normal.cwiseAbs().sum();
    for (int axis = 0; axis < 3; ++axis) {
      for (const Vec3& e : edges) {
        const Vec3 a = Vec3::Unit(axis).cross(e);
        if (a.isZero(0.0)) continue;  // edge parallel to this box axis: nothing to separate
        const double p0 = a.dot(v0), p1 = a.dot(v1), p2 = a.dot(v2);
        axes[axisCount++] = {a, std::min({p0, p1, p2}), std::max({p0, p1, p2}),
                             0.5 * a.cwiseAbs().sum()};
      }
    }
  }

  bool overlapsVoxelCentredAt(const Vec3& c) const {
    if (std::abs(normal.dot(c) - planeOffset) > planeRadius) return false;
    for (int n = 0; n < axisCount; ++n) {
      const Axis& a = axes[n];
      const double t = a.direction.dot(c);
      if (a.minProjection - t > a.radius || a.maxProjection - t < -a.radius) return false;
    }
    return true;
  }
};

// First and last voxel along one axis whose closed interval [i, i+1] meets [lo, hi], clamped.
std::pair<int, int> voxelRange(double lo, double hi, int resolution) {
  const double first = std::max(0.0, std::ceil(lo) - 1.0);
  const double last = std::min(static_cast<double>(resolution - 1), std::floor(hi));
  return {static_cast<int>(first), static_cast<int>(last)};
}

}  // namespace

VoxelGrid voxelize(const Mesh& normalizedMesh, int resolution) {
  VoxelGrid grid(resolution);
  const double n = resolution;
  auto toGrid = [n](const Eigen::Vector3f& p) { return Vec3((p.cast<double>().array() + 0.5) * n); };

  for (const Eigen::Vector3i& tri : normalizedMesh.triangles) {
    const Vec3 v0 = toGrid(normalizedMesh.positions[tri[0]]);
    const Vec3 v1 = toGrid(normalizedMesh.positions[tri[1]]);
    const Vec3 v2 = toGrid(normalizedMesh.positions[tri[2]]);
    if (!v0.allFinite() || !v1.allFinite() || !v2.allFinite()) continue;
    const Vec3 lo = v0.cwiseMin(v1).cwiseMin(v2);
    const Vec3 hi = v0.cwiseMax(v1).cwiseMax(v2);
    const auto [i0, i1] = voxelRange(lo.x(), hi.x(), resolution);
    const auto [j0, j1] = voxelRange(lo.y(), hi.y(), resolution);
    const auto [k0, k1] = voxelRange(lo.z(), hi.z(), resolution);
    if (i0 > i1 || j0 > j1 || k0 > k1) continue;  // entirely outside the grid
    if (i0 == i1 && j0 == j1 && k0 == k1 && lo.minCoeff() >= 0.0 && hi.maxCoeff() <= n) {
      grid.setOccupied({i0, j0, k0});  // the bounding box lies inside one voxel
      continue;
    }
    const TriangleTests tests(v0, v1, v2);
    const int first[3] = {i0, j0, k0}, last[3] = {i1, j1, k1};
    // March along the axis where the normal is largest: in each column of voxels along it only
    // the few near the plane can overlap, so the column is cut to the plane's slab (widened by a
    // voxel against rounding) before the exact test runs. Large tilted triangles would otherwise
    // test their whole bounding box.
    int w = 0;
    tests.normal.cwiseAbs().maxCoeff(&w);
    const int a = (w + 1) % 3, b = (w + 2) % 3;
    const double nw = tests.normal[w];
    for (int ia = first[a]; ia <= last[a]; ++ia) {
      for (int ib = first[b]; ib <= last[b]; ++ib) {
        int lo = first[w], hi = last[w];
        if (nw != 0.0) {
          // |n . c - d| <= r with c[w] = iw + 0.5  <=>  iw + 0.5 in [(d - r - s) / nw, (d + r - s) / nw].
          const double s = tests.normal[a] * (ia + 0.5) + tests.normal[b] * (ib + 0.5);
          double t0 = (tests.planeOffset - tests.planeRadius - s) / nw - 0.5;
          double t1 = (tests.planeOffset + tests.planeRadius - s) / nw - 0.5;
          if (t0 > t1) std::swap(t0, t1);
          lo = std::max(lo, static_cast<int>(std::max(std::floor(t0) - 1.0, -1.0)));
          hi = std::min(hi, static_cast<int>(std::min(std::ceil(t1) + 1.0, static_cast<double>(resolution))));
        }
        for (int iw = lo; iw <= hi; ++iw) {
          int index[3];
          index[a] = ia;
          index[b] = ib;
          index[w] = iw;
          const VoxelIndex v{index[0], index[1], index[2]};
          if (grid.occupied(v)) continue;
          if (tests.overlapsVoxelCentredAt(Vec3(v.i + 0.5, v.j + 0.5, v.k + 0.5))) grid.setOccupied(v);
        }
      }
    }
  }
  return grid;
}

}  // namespace sagrid
