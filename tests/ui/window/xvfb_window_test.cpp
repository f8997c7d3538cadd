// The real GLFW window, once, under xvfb-run: `sagrid render --backend window` opens a window,
// draws the GUI frame and reads it back; the image must match the headless EGL render of the same
// object (both draw through the same frame function).
#include <gtest/gtest.h>

#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"
#include "ui/gl/image.h"

namespace sagrid::ui {
namespace {

TEST(XvfbWindow, WindowFrameMatchesHeadlessFrame) {
  if (sagrid::test::runCommand("command -v xvfb-run").exitCode != 0) {
    GTEST_SKIP()
        << "xvfb-run is not installed (apt-get install xvfb): the real-window test needs it";
  }
  const auto dir = sagrid::test::freshTempDir();
  test::writeSceneObj(dir / "mesh.obj");
  test::writeSceneLabels(dir / "labels.json");
  const std::string common =
      sagrid::test::shellQuote((dir / "mesh.obj").string()) + " --field --size 400x300 ";
  const auto window = sagrid::test::runCommand(
      "xvfb-run -a -s '-screen 0 640x480x24' " +
      sagrid::test::shellQuote(sagrid::test::sagridBinary().string()) + " render " + common +
      "--backend window --screenshot " + sagrid::test::shellQuote((dir / "window.png").string()));
  ASSERT_EQ(window.exitCode, 0) << window.output;
  const auto headless =
      sagrid::test::runSagrid("render " + common + "--backend egl --screenshot " +
                              sagrid::test::shellQuote((dir / "egl.png").string()));
  ASSERT_EQ(headless.exitCode, 0) << headless.output;
  const RgbaImage a = readPng(dir / "window.png");
  const RgbaImage b = readPng(dir / "egl.png");
  ASSERT_EQ(a.width, 400);
  ASSERT_EQ(a.height, 300);
  const ImageDifference d = compareImages(a, b, 12);
  EXPECT_LT(d.differingShare, 0.01) << d.differingPixels << " pixels differ";
}

}  // namespace
}  // namespace sagrid::ui
