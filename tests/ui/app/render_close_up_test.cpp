// `sagrid render --close-up N` frames point N as F does in the GUI (checking a label on a small
// part of a large object meant rendering the whole object and squinting).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"
#include "ui/app/headless_render.h"
#include "ui/gl/image.h"
#include "ui/render/type_colors.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// Share of pixels within `tolerance` of the togglebutton marker colour.
double markerShare(const RgbaImage& image) {
  const Eigen::Vector3f colour = typeColor("togglebutton");
  std::size_t near = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      bool close = true;
      for (int c = 0; c < 3; ++c) close &= std::abs(p[c] - 255.0f * colour[c]) < 40.0f;
      near += close;
    }
  return double(near) / (double(image.width) * image.height);
}

TEST(RenderCloseUp, FramesTheNumberedPoint) {
  const fs::path dir = sagrid::test::freshTempDir();
  test::writeSceneObj(dir / "mesh.obj");
  test::writeSceneLabels(dir / "labels.json");  // point 2: the togglebutton at (-0.3, -0.3, 0)
  RenderOptions options;
  options.mesh = dir / "mesh.obj";
  options.width = 240;
  options.height = 180;
  options.showPanels = false;
  options.screenshot = dir / "whole.png";
  renderScreenshot(options);
  options.closeUpPoint = 2;
  options.screenshot = dir / "close.png";
  renderScreenshot(options);
  // Markers keep their size on screen; the close-up puts point 2 in the middle of the image,
  // where the whole view shows the space between the two points.
  auto centre = [](const RgbaImage& image) {
    const std::uint8_t* p = image.at(image.width / 2, image.height / 2);
    return RgbaImage{1, 1, {p, p + 4}};
  };
  EXPECT_EQ(markerShare(centre(readPng(dir / "close.png"))), 1.0);
  EXPECT_EQ(markerShare(centre(readPng(dir / "whole.png"))), 0.0);

  options.closeUpPoint = 3;
  options.screenshot = dir / "none.png";
  try {
    renderScreenshot(options);
    ADD_FAILURE() << "rendered a point that does not exist";
  } catch (const sagrid::Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("--close-up 3: the object has 2 points"));
  }
  EXPECT_FALSE(fs::exists(dir / "none.png"));
}

}  // namespace
}  // namespace sagrid::ui
