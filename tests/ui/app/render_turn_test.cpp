// `sagrid render --turn A` (View > Controls turned, T, in the GUI) draws the mesh with every toggle
// button's control moved as the exports move it: a block knob turned shows, an object whose
// toggle buttons move nothing draws as modelled.
#include <gtest/gtest.h>

#include <fstream>

#include "core/labels/labels.h"
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
  fs::create_directories(dir);
  std::ofstream obj(dir / "mesh.obj");
  obj << "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nf 1 2 3\nf 1 3 4\n"
         "v 0.12 0.12 0.08\nv 0.28 0.12 0.08\nv 0.28 0.28 0.08\nv 0.12 0.28 0.08\n"
         "v 0.12 0.12 0\nv 0.28 0.12 0\nv 0.28 0.28 0\nv 0.12 0.28 0\n"
         "f 5 6 7\nf 5 7 8\nf 9 10 6\nf 9 6 5\nf 10 11 7\nf 10 7 6\nf 11 12 8\nf 11 8 7\nf 12 9 5\nf 12 5 8\n";
  obj.close();
  ObjectLabels labels;
  labels.object.id = "scene";
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  labels.object.up = "z";
  AffordancePoint point;
  point.type = "togglebutton";
  point.position = toggle;
  labels.affordances.push_back(point);
  writeLabels(dir / "labels.json", labels);
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
