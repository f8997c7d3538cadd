#include "ui/render/texture_contrast.h"

#include <gtest/gtest.h>

#include "core/mesh/mesh.h"

namespace sagrid::ui {
namespace {

// A texture of `dark` grey with `marks` texels of `bright` grey (of 100).
Texture greys(std::uint8_t dark, std::uint8_t bright, int marks) {
  Texture t;
  t.width = 10;
  t.height = 10;
  for (int i = 0; i < 100; ++i)
    for (std::uint8_t v : {i < marks ? bright : dark, i < marks ? bright : dark, i < marks ? bright : dark,
                           std::uint8_t(255)})
      t.rgba.push_back(v);
  return t;
}

TEST(TextureContrast, TheRangeSpansTheTexturesOwnGreysInLinearLight) {
  // Black glass (sRGB 8) with faint grey marks (sRGB 40) on 10 % of it.
  const LuminanceRange range = luminanceRange(greys(8, 40, 10));
  EXPECT_NEAR(range.low, 8.0 / 255.0 / 12.92, 1e-5);      // sRGB 8 is in the linear segment
  EXPECT_NEAR(range.high, 0.0212, 2e-4);                  // sRGB 40 ~ 0.021 linear
  // The marks on 1 % of it are above the 98th percentile: the range is the glass alone, widened.
  const LuminanceRange few = luminanceRange(greys(8, 40, 1));
  EXPECT_NEAR(few.high - few.low, 1.0f / 255.0f, 1e-6);
}

TEST(TextureContrast, ALargeTextureIsReadAtAStrideWithTheSameRange) {
  // 1024 x 1024 texels (16 times the most read): black glass, marks in its first 100 columns.
  Texture t;
  t.width = t.height = 1024;
  t.rgba.assign(std::size_t(1024) * 1024 * 4, 255);
  for (std::size_t i = 0; i < std::size_t(1024) * 1024; ++i)
    for (std::size_t c = 0; c < 3; ++c) t.rgba[4 * i + c] = i % 1024 < 100 ? 40 : 8;
  const LuminanceRange range = luminanceRange(t);
  EXPECT_NEAR(range.low, 8.0 / 255.0 / 12.92, 1e-5);
  EXPECT_NEAR(range.high, 0.0212, 2e-4);
}

TEST(TextureContrast, OneColourOrNothingGivesAUsableRange) {
  const LuminanceRange flat = luminanceRange(greys(128, 128, 0));
  EXPECT_GT(flat.high, flat.low);
  const LuminanceRange black = luminanceRange(greys(0, 0, 0));
  EXPECT_GE(black.low, 0.0f);
  EXPECT_GT(black.high, black.low);
  const LuminanceRange empty = luminanceRange(Texture{});
  EXPECT_EQ(empty.low, 0.0f);
  EXPECT_EQ(empty.high, 1.0f);
  Texture truncated = greys(8, 40, 10);
  truncated.rgba.resize(10);  // fewer bytes than its size says
  EXPECT_EQ(luminanceRange(truncated).high, 1.0f);
}

}  // namespace
}  // namespace sagrid::ui
