#include <gtest/gtest.h>

#include <limits>

#include "core/mesh/mesh.h"

namespace sagrid {
namespace {

// 2 x 1 texels: black on the left, white on the right.
Texture blackWhite() {
  Texture t;
  t.width = 2;
  t.height = 1;
  t.rgba = {0, 0, 0, 255, 255, 255, 255, 255};
  return t;
}

TEST(TextureSample, TexelCentresGiveTheirColourAndUvsRepeat) {
  const Texture t = blackWhite();
  EXPECT_NEAR(t.sample({0.25f, 0.5f}).x(), 0.0f, 1e-6f);
  EXPECT_NEAR(t.sample({0.75f, 0.5f}).x(), 1.0f, 1e-6f);
  EXPECT_NEAR(t.sample({0.5f, 0.5f}).x(), 0.5f, 1e-6f);  // halfway: bilinear
  EXPECT_NEAR(t.sample({1.75f, 0.5f}).x(), 1.0f, 1e-5f);
  EXPECT_NEAR(t.sample({-0.75f, 0.5f}).x(), 0.0f, 1e-5f);
}

TEST(TextureSample, DamagedUvsSampleWhiteInsteadOfAnIndexOutOfRange) {
  const Texture t = blackWhite();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (const Eigen::Vector2f uv : {Eigen::Vector2f(nan, 0.5f), Eigen::Vector2f(0.5f, inf),
                                   Eigen::Vector2f(3e9f, 0.5f), Eigen::Vector2f(-3e9f, -3e9f)}) {
    EXPECT_EQ(t.sample(uv), Eigen::Vector3f::Ones());
  }
}

}  // namespace
}  // namespace sagrid
