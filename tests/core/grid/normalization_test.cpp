#include "core/grid/normalization.h"

#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/mesh/mesh.h"

namespace sagrid {
namespace {

Mesh twoTriangles(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  Mesh mesh;
  mesh.positions = {lo, {hi.x(), lo.y(), lo.z()}, hi, {lo.x(), hi.y(), hi.z()}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TEST(Normalization, FitsUnitCubeLargestExtentOne) {
  const Mesh mesh = twoTriangles({-1.0f, 2.0f, 10.0f}, {3.0f, 3.0f, 11.5f});
  const Normalization n = Normalization::fromMesh(mesh);
  EXPECT_TRUE(n.center.isApprox(Eigen::Vector3f(1.0f, 2.5f, 10.75f)));
  EXPECT_FLOAT_EQ(n.scale, 0.25f);
  const Eigen::AlignedBox3f box = normalizedCopy(mesh, n).bounds();
  EXPECT_FLOAT_EQ(box.min().x(), -0.5f);
  EXPECT_FLOAT_EQ(box.max().x(), 0.5f);
  EXPECT_FLOAT_EQ(box.min().y(), -0.125f);
  EXPECT_FLOAT_EQ(box.max().z(), 0.1875f);
  EXPECT_FLOAT_EQ(n.lengthToMesh(0.5f), 2.0f);
}

TEST(Normalization, RoundTripIsExactToFloatPrecision) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (float size : {1e-3f, 1.0f, 250.0f, 1e6f}) {
    const Eigen::Vector3f offset(3.0f * size, -7.0f * size, 0.5f * size);
    const Mesh mesh = twoTriangles(offset, offset + Eigen::Vector3f(size, 0.3f * size, 2 * size));
    const Normalization n = Normalization::fromMesh(mesh);
    for (int k = 0; k < 200; ++k) {
      const Eigen::Vector3f p = offset + size * Eigen::Vector3f(u(rng), u(rng), u(rng));
      const Eigen::Vector3f back = n.toMesh(n.toNormalized(p));
      // A few float ulps of the coordinates involved.
      const float tolerance = 4 * std::numeric_limits<float>::epsilon() * (offset.norm() + size);
      EXPECT_LE((back - p).cwiseAbs().maxCoeff(), tolerance) << size;
    }
  }
}

TEST(Normalization, HugeButWellScaledMeshIsFine) {
  const Mesh mesh = twoTriangles({-1e9f, -1e9f, 0.0f}, {1e9f, 1e9f, 5e8f});
  EXPECT_FALSE(normalizationProblem(mesh.bounds()).has_value());
  const Normalization n = Normalization::fromMesh(mesh);
  const Eigen::AlignedBox3f box = normalizedCopy(mesh, n).bounds();
  EXPECT_FLOAT_EQ(box.max().x(), 0.5f);
  EXPECT_FLOAT_EQ(box.min().y(), -0.5f);
  EXPECT_FLOAT_EQ(box.max().z(), 0.125f);
}

TEST(Normalization, RejectsBoxesItCannotNormalize) {
  using ::testing::HasSubstr;
  EXPECT_THAT(*normalizationProblem(Eigen::AlignedBox3f()), HasSubstr("no vertices"));
  const Eigen::Vector3f p(1, 2, 3);
  EXPECT_THAT(*normalizationProblem(Eigen::AlignedBox3f(p, p)), HasSubstr("no extent"));
  // A 1-unit object a billion units from the origin: float cannot resolve it.
  const Eigen::Vector3f far(1e9f, 0, 0);
  EXPECT_THAT(*normalizationProblem(Eigen::AlignedBox3f(far, far + Eigen::Vector3f::Ones())),
              HasSubstr("too small"));
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(normalizationProblem(Eigen::AlignedBox3f(p, Eigen::Vector3f(inf, 3, 4))).has_value());
  EXPECT_TRUE(normalizationProblem(
                  Eigen::AlignedBox3f(Eigen::Vector3f(-3e38f, 0, 0), Eigen::Vector3f(3e38f, 1, 1)))
                  .has_value());
  EXPECT_THROW(Normalization::fromBounds(Eigen::AlignedBox3f(p, p)), Error);
  // A flat (planar) mesh is fine: only the largest extent matters.
  EXPECT_FALSE(normalizationProblem(Eigen::AlignedBox3f(p, p + Eigen::Vector3f(1, 1, 0))).has_value());
}

}  // namespace
}  // namespace sagrid
