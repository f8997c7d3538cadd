// G (View > Plain grey) draws a model whose materials are black in one light grey, so its shape
// shows (seen curating the wild pool in the window: an electric stove rendered black, wireframe
// included, and its points were accepted unseen); M a colour per material; B stretches each
// texture's own contrast, so marks printed faintly in it show (a ceramic hob's touch keys, grey on
// black glass, that neither of the others shows).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <Eigen/Core>

#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// Mean of the red, green and blue values over the middle quarter of the image.
double middleBrightness(const RgbaImage& image) {
  double sum = 0;
  int count = 0;
  for (int y = image.height / 4; y < 3 * image.height / 4; ++y)
    for (int x = image.width / 4; x < 3 * image.width / 4; ++x, ++count)
      sum += (image.at(x, y)[0] + image.at(x, y)[1] + image.at(x, y)[2]) / 3.0;
  return sum / count;
}

// A flat model at z = 0 written as DIR/NAME/mesh.obj with its .mtl, opened in `s` and seen
// straight from above with nothing else drawn.
void openFlatFromAbove(test::ScriptedApp& s, const fs::path& dir, const std::string& name,
                       const std::string& mtl, const std::string& obj) {
  fs::create_directories(dir / name);
  std::ofstream(dir / name / "mesh.mtl") << mtl;
  std::ofstream(dir / name / "mesh.obj") << "mtllib mesh.mtl\n" << obj;
  s.app->session().openObject(dir / name / "mesh.obj", dir / name / "labels.json");
  s.app->session().view().showGrid = false;
  s.app->session().view().showAxes = false;
  s.app->session().view().showPanels = false;
  s.frame({});
  s.app->session().camera().set({0, 0, 0}, 2.5f, -1.5707963f, 1.5f);  // straight down on it
  s.frame({});
}

TEST(RenderPlainShading, GShowsTheShapeOfABlackModel) {
  const fs::path dir = sagrid::test::freshTempDir();
  test::ScriptedApp s(dir);
  openFlatFromAbove(s, dir, "black", "newmtl black\nKd 0 0 0\n",
                    "usemtl black\nv -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nf 1 2 3\nf 1 3 4\n");
  const double black = middleBrightness(s.app->capture());
  s.key(GLFW_KEY_G);
  EXPECT_EQ(s.app->session().view().surface, SurfaceColouring::PlainGrey);
  s.frame({});
  const double plain = middleBrightness(s.app->capture());
  EXPECT_GT(plain, black + 60.0) << "black " << black << ", plain " << plain;
}

// Mean colour over a vertical band of the image's middle rows, from x0 to x1 (fractions of the width).
Eigen::Vector3d bandColour(const RgbaImage& image, double x0, double x1) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (int y = 2 * image.height / 5; y < 3 * image.height / 5; ++y)
    for (int x = int(x0 * image.width); x < int(x1 * image.width); ++x, ++count)
      for (int c = 0; c < 3; ++c) sum[c] += image.at(x, y)[c];
  return sum / count;
}

TEST(RenderPlainShading, MShowsPartsThatDifferOnlyByMaterial) {
  // Two halves of a plate in two materials of almost the same black (keys of their own material
  // on a glass top): alike as modelled, two colours with M; G then turns M off.
  const fs::path dir = sagrid::test::freshTempDir();
  test::ScriptedApp s(dir);
  openFlatFromAbove(s, dir, "hob", "newmtl glass\nKd 0.02 0.02 0.02\nnewmtl keys\nKd 0.03 0.03 0.03\n",
                    "v -0.5 -0.5 0\nv 0 -0.5 0\nv 0 0.5 0\nv -0.5 0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\n"
                    "usemtl glass\nf 1 2 3\nf 1 3 4\nusemtl keys\nf 2 5 6\nf 2 6 3\n");
  auto halvesApart = [&] {
    const RgbaImage image = s.app->capture();
    return (bandColour(image, 0.30, 0.45) - bandColour(image, 0.55, 0.70)).norm();
  };
  const double modelled = halvesApart();
  s.key(GLFW_KEY_M);
  EXPECT_EQ(s.app->session().view().surface, SurfaceColouring::ByMaterial);
  s.frame({});
  const double byMaterial = halvesApart();
  EXPECT_GT(byMaterial, modelled + 60.0) << "modelled " << modelled << ", by material " << byMaterial;
  s.key(GLFW_KEY_G);
  EXPECT_EQ(s.app->session().view().surface, SurfaceColouring::PlainGrey);
  s.key(GLFW_KEY_G);
  EXPECT_EQ(s.app->session().view().surface, SurfaceColouring::Modelled);
}

TEST(RenderPlainShading, BShowsMarksPrintedFaintlyInATexture) {
  // A black glass texture whose right half holds a printed mark 12 levels brighter (out of 255),
  // on one material: alike as modelled, by material and in plain grey; far apart with B.
  const fs::path dir = sagrid::test::freshTempDir();
  fs::create_directories(dir / "hob");
  RgbaImage glass;
  glass.width = glass.height = 32;
  glass.pixels.assign(32 * 32 * 4, 255);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) glass.at(x, y)[c] = x < 16 ? 8 : 20;
  writePng(dir / "hob" / "glass.png", glass);
  test::ScriptedApp s(dir);
  openFlatFromAbove(s, dir, "hob", "newmtl glass\nKd 1 1 1\nmap_Kd glass.png\n",
                    "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\n"
                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl glass\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
  auto halvesApart = [&] {
    s.frame({});
    const RgbaImage image = s.app->capture();
    return (bandColour(image, 0.30, 0.45) - bandColour(image, 0.55, 0.70)).norm();
  };
  const double modelled = halvesApart();
  s.key(GLFW_KEY_B);
  EXPECT_EQ(s.app->session().view().surface, SurfaceColouring::TextureContrast);
  const double contrast = halvesApart();
  EXPECT_GT(contrast, modelled + 150.0) << "modelled " << modelled << ", texture contrast " << contrast;
  // The other views do not show it (their halves differ by the light's fall across the plate).
  s.key(GLFW_KEY_M);
  EXPECT_LT(halvesApart(), contrast / 4);
  s.key(GLFW_KEY_G);
  EXPECT_LT(halvesApart(), contrast / 4);
}

}  // namespace
}  // namespace sagrid::ui
