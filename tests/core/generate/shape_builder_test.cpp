#include "core/generate/shape_builder.h"

#include <map>
#include <utility>

#include <gtest/gtest.h>

#include "core/generate/random.h"

namespace sagrid::gen {
namespace {

// Every undirected edge (by welded position) is used by exactly two triangles: the part is closed.
bool isClosed(const Mesh& mesh) {
  auto key = [&](int v) {
    const Eigen::Vector3f& p = mesh.positions[v];
    return std::make_tuple(std::lround(p.x() * 1e5), std::lround(p.y() * 1e5), std::lround(p.z() * 1e5));
  };
  std::map<std::pair<std::tuple<long, long, long>, std::tuple<long, long, long>>, int> edges;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      auto a = key(t[k]), b = key(t[(k + 1) % 3]);
      if (a == b) continue;  // degenerate edge of a collapsed corner
      if (b < a) std::swap(a, b);
      ++edges[{a, b}];
    }
  }
  for (const auto& [edge, count] : edges) {
    if (count % 2 != 0) return false;
  }
  return !edges.empty();
}

float signedVolume(const Mesh& mesh) {
  double v = 0;
  for (const auto& t : mesh.triangles) {
    v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]])) / 6.0;
  }
  return static_cast<float>(v);
}

TEST(ShapeBuilder, BoxHasSizeVolumeAndOutwardWinding) {
  ShapeBuilder b;
  const int m = b.material("steel", Vec3(0.7f, 0.7f, 0.7f));
  b.box(translation(1, 2, 3), Vec3(0.4f, 0.2f, 0.1f), m, 0, 0, 3);
  const Mesh mesh = std::move(b).build();
  EXPECT_EQ(mesh.triangleCount(), 6u * 9u * 2u);
  EXPECT_TRUE(mesh.bounds().min().isApprox(Eigen::Vector3f(0.8f, 1.9f, 2.95f), 1e-5f));
  EXPECT_TRUE(mesh.bounds().max().isApprox(Eigen::Vector3f(1.2f, 2.1f, 3.05f), 1e-5f));
  EXPECT_NEAR(signedVolume(mesh), 0.4f * 0.2f * 0.1f, 1e-5f);  // positive: normals point out
  EXPECT_TRUE(isClosed(mesh));
  EXPECT_TRUE(mesh.uvs.empty());  // no texture used
}

TEST(ShapeBuilder, BevelledBoxKeepsExtentAndRoundsCorners) {
  ShapeBuilder b;
  b.box(Affine::Identity(), Vec3(1, 1, 1), b.material("m", Vec3::Ones()), 0.1f, 3);
  const Mesh mesh = std::move(b).build();
  EXPECT_NEAR(mesh.bounds().max().x(), 0.5f, 1e-5f);
  // The corner is cut: no vertex reaches (0.5, 0.5, 0.5).
  float maxSum = 0;
  for (const auto& p : mesh.positions) maxSum = std::max(maxSum, p.sum());
  EXPECT_LT(maxSum, 1.45f);
  EXPECT_GT(signedVolume(mesh), 0.95f);
  EXPECT_LT(signedVolume(mesh), 1.0f);
  EXPECT_TRUE(isClosed(mesh));
}

TEST(ShapeBuilder, CylinderVolumeApproachesPiR2H) {
  ShapeBuilder b;
  b.cylinder(translation(0, 0, 1), 0.5f, 0, 2, 64, b.material("m", Vec3::Ones()));
  const Mesh mesh = std::move(b).build();
  EXPECT_NEAR(signedVolume(mesh), 3.14159f * 0.25f * 2, 0.01f);
  EXPECT_NEAR(mesh.bounds().min().z(), 1.0f, 1e-6f);
  EXPECT_NEAR(mesh.bounds().max().z(), 3.0f, 1e-6f);
  EXPECT_TRUE(isClosed(mesh));
}

TEST(ShapeBuilder, TubeFollowsPathWithRadius) {
  ShapeBuilder b;
  b.tube({Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 1)}, 0.1f, 16, b.material("m", Vec3::Ones()));
  const Mesh mesh = std::move(b).build();
  EXPECT_NEAR(mesh.bounds().max().x(), 1.0f, 1e-5f);  // end cap plane
  EXPECT_NEAR(mesh.bounds().min().z(), 0.0f, 1e-5f);  // start cap plane
  EXPECT_GT(signedVolume(mesh), 0.0f);
  EXPECT_TRUE(isClosed(mesh));
}

TEST(ShapeBuilder, LoftMatchesRingsOfZeroAndNonZeroRadius) {
  // Rings with and without rounded corners must sample the same number of points.
  ShapeBuilder b;
  RoundedRect a{Vec2(0, 0), Vec2(0.3f, 0.2f), 0.05f, 0};
  RoundedRect c{Vec2(0, 0), Vec2(0.25f, 0.15f), 0.0f, 0.2f};
  b.loft(Affine::Identity(), {a, c}, 4, b.material("m", Vec3::Ones()), true, true);
  const Mesh mesh = std::move(b).build();
  EXPECT_GT(signedVolume(mesh), 0.0f);
  EXPECT_TRUE(isClosed(mesh));
}

TEST(ShapeBuilder, PlateWithHoleHasAreaOfOuterMinusHole) {
  ShapeBuilder b;
  RoundedRect hole{Vec2(0, 0.05f), Vec2(0.2f, 0.15f), 0.0f, 0};
  b.plateWithHole(Affine::Identity(), Vec2(0.5f, 0.3f), hole, 0, 0.04f, 3, b.material("m", Vec3::Ones()));
  const Mesh mesh = std::move(b).build();
  EXPECT_NEAR(signedVolume(mesh), (1.0f * 0.6f - 0.4f * 0.3f) * 0.04f, 1e-5f);
  EXPECT_TRUE(isClosed(mesh));
}

TEST(Rng, SameSeedSameSequenceAndRangesHold) {
  Rng a(42), b(42);
  int hits[3] = {0, 0, 0};
  for (int i = 0; i < 3000; ++i) {
    const double u = a.uniform();
    EXPECT_EQ(u, b.uniform());
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
    const int k = a.uniformInt(-1, 1);
    b.uniformInt(-1, 1);
    ASSERT_GE(k, -1);
    ASSERT_LE(k, 1);
    ++hits[k + 1];
  }
  for (int h : hits) EXPECT_GT(h, 800);
  EXPECT_NE(deriveSeed(1, "stove", 0), deriveSeed(1, "stove", 1));
  EXPECT_NE(deriveSeed(1, "stove", 0), deriveSeed(1, "sink", 0));
}

TEST(Rng, WeightedFollowsWeights) {
  Rng rng(7);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 10000; ++i) ++counts[rng.weighted({1.0, 0.0, 3.0})];
  EXPECT_EQ(counts[1], 0);
  EXPECT_NEAR(counts[2] / 10000.0, 0.75, 0.03);
}

}  // namespace
}  // namespace sagrid::gen
