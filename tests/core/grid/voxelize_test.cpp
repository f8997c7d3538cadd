// Voxelization against an independent exact reference: every voxel is tested against every
// triangle by solving "is there a point of the triangle inside the closed cube" as a small linear
// feasibility problem in exact integer arithmetic (no separating axes involved). The analytic
// meshes are built on a dyadic lattice (1/4096 of a voxel) so the float input is exact too.
#include "core/grid/voxelize.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/mesh/mesh.h"

namespace sagrid {
namespace {

constexpr int kSubBits = 12;
constexpr std::int64_t kSub = std::int64_t{1} << kSubBits;  // lattice steps per voxel
using Int = __int128;
using Lattice = Eigen::Matrix<std::int64_t, 3, 1>;

// A triangle soup on the lattice, in grid units times kSub.
struct LatticeMesh {
  std::vector<Lattice> vertices;
  std::vector<Eigen::Vector3i> triangles;

  int add(const Eigen::Vector3d& gridPoint) {
    vertices.push_back((gridPoint * static_cast<double>(kSub)).array().round().cast<std::int64_t>());
    return static_cast<int>(vertices.size()) - 1;
  }
  void addTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    triangles.emplace_back(add(a), add(b), add(c));
  }
  void append(const LatticeMesh& other) {
    const int base = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    for (const auto& t : other.triangles) triangles.emplace_back(t.array() + base);
  }

  // The same mesh in the normalized frame, as voxelize() takes it; exact for power-of-two N.
  Mesh normalized(int resolution) const {
    Mesh mesh;
    for (const Lattice& v : vertices) {
      const Eigen::Vector3d g = v.cast<double>() / static_cast<double>(kSub);
      mesh.positions.push_back((g / resolution).array().cast<float>() - 0.5f);
      EXPECT_EQ(static_cast<double>(mesh.positions.back().x()), g.x() / resolution - 0.5);
    }
    mesh.triangles = triangles;
    return mesh;
  }
};

// Exact: does the closed triangle (a, b, c) meet the closed box [lo, hi]? Points of the triangle
// are a + s (b - a) + t (c - a) with s, t >= 0, s + t <= 1; with the six box constraints that is
// a set of nine half-planes in (s, t). A non-empty bounded intersection has a vertex where two
// independent constraint lines cross, so trying every such crossing decides feasibility.
bool referenceOverlap(const Lattice& a, const Lattice& b, const Lattice& c, const Lattice& lo,
                      const Lattice& hi) {
  struct HalfPlane { Int x, y, r; };  // x s + y t <= r
  std::vector<HalfPlane> h{{-1, 0, 0}, {0, -1, 0}, {1, 1, 1}};
  for (int d = 0; d < 3; ++d) {
    const Int e1 = b[d] - a[d], e2 = c[d] - a[d];
    h.push_back({e1, e2, Int(hi[d]) - a[d]});
    h.push_back({-e1, -e2, Int(a[d]) - lo[d]});
  }
  for (std::size_t p = 0; p < h.size(); ++p) {
    for (std::size_t q = p + 1; q < h.size(); ++q) {
      Int det = h[p].x * h[q].y - h[p].y * h[q].x;
      if (det == 0) continue;
      Int sNum = h[p].r * h[q].y - h[q].r * h[p].y;
      Int tNum = h[p].x * h[q].r - h[q].x * h[p].r;
      if (det < 0) det = -det, sNum = -sNum, tNum = -tNum;
      bool inside = true;
      for (const auto& k : h) {
        if (k.x * sNum + k.y * tNum > k.r * det) {
          inside = false;
          break;
        }
      }
      if (inside) return true;
    }
  }
  return false;
}

VoxelGrid referenceVoxelize(const LatticeMesh& mesh, int resolution) {
  VoxelGrid grid(resolution);
  for (int i = 0; i < resolution; ++i)
    for (int j = 0; j < resolution; ++j)
      for (int k = 0; k < resolution; ++k) {
        const Lattice lo = Lattice(i, j, k) * kSub;
        const Lattice hi = lo + Lattice::Constant(kSub);
        for (const auto& t : mesh.triangles) {
          const Lattice& a = mesh.vertices[t[0]];
          const Lattice& b = mesh.vertices[t[1]];
          const Lattice& c = mesh.vertices[t[2]];
          // Cheap and obviously safe: all three vertices beyond one face means no overlap.
          bool beyond = false;
          for (int d = 0; d < 3 && !beyond; ++d) {
            beyond = (a[d] < lo[d] && b[d] < lo[d] && c[d] < lo[d]) ||
                     (a[d] > hi[d] && b[d] > hi[d] && c[d] > hi[d]);
          }
          if (!beyond && referenceOverlap(a, b, c, lo, hi)) {
            grid.setOccupied({i, j, k});
            break;
          }
        }
      }
  return grid;
}

void expectMatchesReference(const LatticeMesh& mesh, int resolution) {
  const VoxelGrid expected = referenceVoxelize(mesh, resolution);
  const VoxelGrid actual = voxelize(mesh.normalized(resolution), resolution);
  int mismatches = 0;
  for (std::size_t i = 0; i < expected.voxelCount(); ++i) {
    if (expected.occupancy()[i] != actual.occupancy()[i] && ++mismatches <= 10) {
      const VoxelIndex v = expected.fromLinear(i);
      ADD_FAILURE() << "voxel (" << v.i << "," << v.j << "," << v.k << ") reference "
                    << int(expected.occupancy()[i]) << " voxelize " << int(actual.occupancy()[i]);
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(actual.occupiedCount(), expected.occupiedCount());
  EXPECT_GT(expected.occupiedCount(), 0u);
}

// Icosphere in grid units.
LatticeMesh sphere(const Eigen::Vector3d& centre, double radius, int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                 {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                 {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::vector<Eigen::Vector3i> next;
    for (const auto& tri : f) {
      int m[3];
      for (int e = 0; e < 3; ++e) {
        v.push_back((v[tri[e]] + v[tri[(e + 1) % 3]]) / 2);
        m[e] = static_cast<int>(v.size()) - 1;
      }
      next.emplace_back(tri[0], m[0], m[2]);
      next.emplace_back(tri[1], m[1], m[0]);
      next.emplace_back(tri[2], m[2], m[1]);
      next.emplace_back(m[0], m[1], m[2]);
    }
    f = next;
  }
  LatticeMesh mesh;
  for (const auto& tri : f) {
    mesh.addTriangle(centre + radius * v[tri[0]].normalized(), centre + radius * v[tri[1]].normalized(),
                     centre + radius * v[tri[2]].normalized());
  }
  return mesh;
}

// Axis-aligned box as 12 triangles, optionally rotated about its centre.
LatticeMesh box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  const Eigen::Vector3d centre = (lo + hi) / 2;
  auto corner = [&](int bits) {
    const Eigen::Vector3d p(bits & 1 ? hi.x() : lo.x(), bits & 2 ? hi.y() : lo.y(),
                            bits & 4 ? hi.z() : lo.z());
    return Eigen::Vector3d(centre + rotation * (p - centre));
  };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  LatticeMesh mesh;
  for (const auto& q : quads) {
    mesh.addTriangle(corner(q[0]), corner(q[1]), corner(q[2]));
    mesh.addTriangle(corner(q[0]), corner(q[2]), corner(q[3]));
  }
  return mesh;
}

TEST(Voxelize, SphereMatchesReference) {
  expectMatchesReference(sphere({8.1, 7.9, 8.05}, 6.3, 2), 16);
  expectMatchesReference(sphere({16.2, 15.9, 16.1}, 12.7, 3), 32);
}

TEST(Voxelize, SmallSphereOnCoarseGrid) {
  expectMatchesReference(sphere({4.0, 4.0, 4.0}, 1.5, 1), 8);  // centre on a voxel corner
}

TEST(Voxelize, AxisAlignedCubeOnVoxelBoundariesMatchesReference) {
  // Faces lie exactly on voxel faces: the closed test must occupy both layers touching a face.
  const LatticeMesh cube = box({4, 4, 4}, {12, 12, 12});
  expectMatchesReference(cube, 16);
  const VoxelGrid grid = voxelize(cube.normalized(16), 16);
  EXPECT_TRUE(grid.occupied({3, 8, 8}));
  EXPECT_TRUE(grid.occupied({4, 8, 8}));
  EXPECT_FALSE(grid.occupied({5, 8, 8}));
  EXPECT_FALSE(grid.occupied({2, 8, 8}));
  // Per face: the 10x10 footprint on both sides of the plane, overlapping at the edges: the
  // occupied set is the 10^3 shell minus the 6^3 interior, i.e. a 10^3 - 6^3 = 784 block shell.
  EXPECT_EQ(grid.occupiedCount(), 10u * 10 * 10 - 6u * 6 * 6);
}

TEST(Voxelize, RotatedCubeMatchesReference) {
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  expectMatchesReference(box({4.3, 5.1, 4.7}, {11.2, 10.6, 12.1}, r), 16);
}

TEST(Voxelize, ThinPlatesMatchReference) {
  LatticeMesh plates;
  // One lattice step thick, inside a voxel layer.
  plates.append(box({2.25, 2.5, 5.5}, {13.5, 13.25, 5.5 + 1.0 / kSub}));
  // A single-sided plate exactly on the voxel boundary z = 10: occupies layers 9 and 10.
  plates.addTriangle({1, 1, 10}, {15, 1, 10}, {15, 15, 10});
  plates.addTriangle({1, 1, 10}, {15, 15, 10}, {1, 15, 10});
  // A tilted thin sliver spanning many voxels.
  plates.addTriangle({0.3, 0.2, 0.1}, {15.7, 3.1, 14.9}, {15.7, 3.1 + 1.0 / kSub, 14.9});
  expectMatchesReference(plates, 16);
  const VoxelGrid grid = voxelize(plates.normalized(16), 16);
  EXPECT_TRUE(grid.occupied({8, 8, 9}));
  EXPECT_TRUE(grid.occupied({8, 8, 10}));
  EXPECT_TRUE(grid.occupied({8, 8, 5}));
  EXPECT_FALSE(grid.occupied({8, 8, 4}));
  EXPECT_FALSE(grid.occupied({8, 8, 6}));
}

TEST(Voxelize, SingleTrianglesMatchReference) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> coord(-1.0, 9.0);  // sometimes outside the 8^3 grid
  for (int n = 0; n < 40; ++n) {
    LatticeMesh mesh;
    mesh.addTriangle({coord(rng), coord(rng), coord(rng)}, {coord(rng), coord(rng), coord(rng)},
                     {coord(rng), coord(rng), coord(rng)});
    SCOPED_TRACE("random triangle " + std::to_string(n));
    const VoxelGrid expected = referenceVoxelize(mesh, 8);
    const VoxelGrid actual = voxelize(mesh.normalized(8), 8);
    EXPECT_EQ(actual.occupancy(), expected.occupancy());
  }
}

TEST(Voxelize, TinyAndDegenerateTriangles) {
  LatticeMesh mesh;
  mesh.addTriangle({2.25, 2.5, 2.75}, {2.5, 2.5, 2.75}, {2.25, 2.75, 2.8});  // inside one voxel
  mesh.addTriangle({5.5, 0.5, 0.5}, {6.5, 0.5, 0.5}, {7.5, 0.5, 0.5});        // a segment
  mesh.addTriangle({1.5, 6.5, 6.0}, {1.5, 6.5, 6.0}, {1.5, 6.5, 6.0});        // a point on a face
  mesh.addTriangle({4, 4, 4}, {4, 4, 4}, {4, 4, 4});                          // a voxel corner
  expectMatchesReference(mesh, 8);
  const VoxelGrid grid = voxelize(mesh.normalized(8), 8);
  EXPECT_TRUE(grid.occupied({2, 2, 2}));
  for (int i = 3; i <= 4; ++i)
    for (int j = 3; j <= 4; ++j)
      for (int k = 3; k <= 4; ++k) EXPECT_TRUE(grid.occupied({i, j, k}));  // all 8 at the corner
  EXPECT_TRUE(grid.occupied({1, 6, 5}));
  EXPECT_TRUE(grid.occupied({1, 6, 6}));
}

TEST(Voxelize, MeshCrossingTheGridBoundaryMatchesReference) {
  // A sphere poking out of two faces of the grid, and a box enclosing the grid's corner.
  LatticeMesh mesh = sphere({1.3, 7.2, 4.1}, 3.6, 2);
  mesh.append(box({5.5, -2.25, 6.5}, {10.25, 2.5, 9.75}));
  expectMatchesReference(mesh, 8);
}

TEST(Voxelize, TriangleEntirelyOutsideOccupiesNothing) {
  LatticeMesh mesh;
  mesh.addTriangle({9, 9, 9}, {12, 9, 9}, {9, 12, 9});
  mesh.addTriangle({-3, 1, 1}, {-1, 1, 1}, {-1, 4, 2});
  const VoxelGrid grid = voxelize(mesh.normalized(8), 8);
  EXPECT_EQ(grid.occupiedCount(), 0u);
  EXPECT_EQ(referenceVoxelize(mesh, 8).occupiedCount(), 0u);
}

TEST(Voxelize, NonPowerOfTwoResolution) {
  // Floats are then not exact on the lattice, so only compare away from ties: a generic sphere.
  const LatticeMesh mesh = sphere({6.1, 5.9, 6.05}, 4.3, 2);
  Mesh normalized;
  for (const Lattice& v : mesh.vertices) {
    normalized.positions.push_back((v.cast<double>() / kSub / 12.0).array().cast<float>() - 0.5f);
  }
  normalized.triangles = mesh.triangles;
  EXPECT_EQ(voxelize(normalized, 12).occupancy(), referenceVoxelize(mesh, 12).occupancy());
}

}  // namespace
}  // namespace sagrid
