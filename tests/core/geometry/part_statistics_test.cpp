#include "core/geometry/part_statistics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// A counter 1 m x 0.6 m x 0.05 m with `caps` equal flat squares `width` across standing on it,
// and `knobs` equal cubes 3 cm across in a row on its front.
Mesh counter(int caps, float width, int knobs = 0) {
  Mesh mesh = test::box({0, 0, 0}, {1.0f, 0.6f, 0.05f});
  for (int i = 0; i < caps; ++i) {
    const Eigen::Vector3f lo(0.1f + 0.25f * static_cast<float>(i), 0.2f, 0.05f);
    test::append(mesh, test::box(lo, lo + Eigen::Vector3f(width, width, 0.02f)));
  }
  for (int i = 0; i < knobs; ++i) {
    const Eigen::Vector3f lo(0.1f + 0.15f * static_cast<float>(i), -0.03f, 0.01f);
    test::append(mesh, test::box(lo, lo + Eigen::Vector3f(0.03f, 0.03f, 0.03f)));
  }
  return mesh;
}

Mesh scaled(Mesh mesh, float factor, const Eigen::Vector3f& shift) {
  for (auto& p : mesh.positions) p = factor * p + shift;
  return mesh;
}

TEST(PartStatistics, AFamilyOfCopiesIsCountedWithItsWidthAndHeight) {
  const auto s = partStatistics(counter(4, 0.12f, 5));
  EXPECT_FLOAT_EQ(s[0], std::log1p(10.0f));  // the counter, 4 caps, 5 knobs
  EXPECT_FLOAT_EQ(s[1], std::log1p(9.0f));   // the counter is no instance part
  // The knobs are the largest family, low on the object; the caps the second, on top.
  EXPECT_FLOAT_EQ(s[2], std::log1p(5.0f));
  EXPECT_NEAR(s[3], 0.03f, 1e-5f);
  EXPECT_LT(s[4], 0.5f);
  EXPECT_FLOAT_EQ(s[6], std::log1p(4.0f));
  EXPECT_NEAR(s[7], 0.12f, 1e-5f);
  EXPECT_GT(s[8], 0.8f);
  // The caps are the round flat family (the cubes are round but not flat).
  EXPECT_FLOAT_EQ(s[9], std::log1p(4.0f));
  EXPECT_NEAR(s[10], 0.12f, 1e-5f);
}

TEST(PartStatistics, WithoutCopiesOrPartsTheFamiliesAreZero) {
  const auto bare = partStatistics(counter(0, 0.12f));
  EXPECT_FLOAT_EQ(bare[0], std::log1p(1.0f));
  for (int i = 1; i < 12; ++i) EXPECT_EQ(bare[std::size_t(i)], 0.0f) << i;
  // One cap: a family of one, no second family.
  const auto one = partStatistics(counter(1, 0.12f));
  EXPECT_FLOAT_EQ(one[2], std::log1p(1.0f));
  EXPECT_EQ(one[6], 0.0f);
  for (float v : partStatistics(Mesh{})) EXPECT_EQ(v, 0.0f);
}

TEST(PartStatistics, TheyDoNotDependOnTheFilesUnitsOrPlace) {
  const Mesh metres = counter(4, 0.12f, 5);
  const auto a = partStatistics(metres);
  const auto b = partStatistics(scaled(metres, 100.0f, {3, -2, 7}));  // centimetres, elsewhere
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-4f) << i;
}

}  // namespace
}  // namespace sagrid
