// `sagrid render --turn A` (View > Controls turned, T, in the GUI) draws the mesh with every toggle
// button's control moved as the exports move it: a block knob turned shows, an object whose
// toggle buttons move nothing draws as modelled.
#include <gtest/gtest.h>

#include "support/analytic_meshes.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"
#include "ui/app/headless_render.h"
#include "ui/gl/image.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// The share of pixels that differ between two images of one size by more than a little.
double differingShare(const RgbaImage& a, const RgbaImage& b) {
  std::size_t differ = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c])) > 12) {
          ++differ;
          break;
        }
  return double(differ) / (double(a.width) * a.height);
}

// A 1 m plate with a 16 x 16 x 8 cm block knob on it at (0.2, 0.2), its toggle point at `toggle`.
fs::path writeObject(const fs::path& dir, const Eigen::Vector3f& toggle) {
  Mesh mesh = sagrid::test::box({-0.5f, -0.5f, -0.01f}, {0.5f, 0.5f, 0.0f});
  sagrid::test::append(mesh, sagrid::test::box({0.12f, 0.12f, 0.0f}, {0.28f, 0.28f, 0.08f}));
  sagrid::test::writeLabelledObject(dir, mesh, {sagrid::test::affordance("togglebutton", toggle)}, "scene",
                                    "stove");
  return dir / "mesh.obj";
}

RgbaImage render(const fs::path& mesh, float turn, const fs::path& png) {
  RenderOptions options;
  options.mesh = mesh;
  options.width = 240;
  options.height = 180;
  options.showPanels = false;
  options.yawDegrees = 30.0f;
  options.pitchDegrees = 50.0f;
  options.closeUpPoint = 1;
  options.controlTurn = turn;
  options.screenshot = png;
  renderScreenshot(options);
  return readPng(png);
}

TEST(RenderTurn, AKnobTurnedShowsAndNothingElseMoves) {
  const fs::path dir = sagrid::test::freshTempDir();
  // On the block's top: the block is the knob, turned 0.6 rad about z.
  const fs::path knob = writeObject(dir / "knob", {0.2f, 0.2f, 0.08f});
  const RgbaImage still = render(knob, 0.0f, dir / "still.png");
  const RgbaImage turned = render(knob, 0.6f, dir / "turned.png");
  EXPECT_GT(differingShare(still, turned), 0.02);  // about 6 %: the block and its highlight
  // On the plate away from the block: a printed key (a disc) moves no triangle.
  const fs::path printed = writeObject(dir / "printed", {-0.3f, -0.3f, 0.0f});
  EXPECT_EQ(differingShare(render(printed, 0.0f, dir / "p0.png"), render(printed, 0.6f, dir / "p1.png")), 0.0);
}

}  // namespace
}  // namespace sagrid::ui
