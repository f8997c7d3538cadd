#include "core/plot/plot.h"

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <cmath>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "support/test_paths.h"

namespace sagrid::plot {
namespace {

TEST(Plot, CanvasDrawsLinesRectsAndText) {
  Canvas c(40, 20);
  c.line(0, 10, 39, 10, {255, 0, 0});
  EXPECT_EQ(c.at(20, 10), (Color{255, 0, 0}));
  EXPECT_EQ(c.at(20, 5), (Color{255, 255, 255}));
  c.fillRect(2, 2, 4, 4, {0, 0, 255});
  EXPECT_EQ(c.at(3, 3), (Color{0, 0, 255}));
  Canvas t(60, 20);
  t.text(1, 1, "AB", {0, 0, 0});
  int dark = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 60; ++x) dark += t.at(x, y)[0] == 0;
  EXPECT_GT(dark, 10);
  EXPECT_GT(Canvas::textWidth("ABC"), Canvas::textWidth("A"));
}

TEST(Plot, LinePlotAndBarChartWriteDecodablePngs) {
  const auto dir = test::freshTempDir();
  LinePlot plot;
  plot.title = "loss";
  plot.series.push_back({"train", {1, 2, 3}, {1.0, 0.5, 0.25}});
  writeLinePlotPng(dir / "loss.png", plot, 320, 200);
  int w = 0, h = 0, n = 0;
  const std::string bytes = readFileBytes(dir / "loss.png");
  unsigned char* pixels =
      stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                            static_cast<int>(bytes.size()), &w, &h, &n, 3);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(w, 320);
  EXPECT_EQ(h, 200);
  int blue = 0;  // the series colour appears
  for (int i = 0; i < w * h; ++i) blue += pixels[3 * i] == 31 && pixels[3 * i + 2] == 180;
  stbi_image_free(pixels);
  EXPECT_GT(blue, 50);

  BarChart chart;
  chart.title = "error";
  chart.methods = {"a", "b"};
  chart.groups = {{"x", {0.1, 0.2}}, {"y", {0.3, std::nan("")}}};
  writeBarChartPng(dir / "bars.png", chart);
  EXPECT_GT(std::filesystem::file_size(dir / "bars.png"), 100u);
  EXPECT_THROW(writeBarChartPng(dir / "none.png", BarChart{}), InvalidArgument);
  EXPECT_THROW(writeLinePlotPng(dir / "none.png", LinePlot{}), InvalidArgument);
}

}  // namespace
}  // namespace sagrid::plot
