// Image baselines of the headless render (EGL): the scene alone and the full window with panels.
// Per-pixel tolerance plus a maximum share of differing pixels; on failure the actual image and a
// diff are written next to the baseline. Regenerate with SAGRID_UPDATE_BASELINES=1.
#include <gtest/gtest.h>

#include <cstdlib>

#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"
#include "ui/gl/image.h"

namespace sagrid::ui {
namespace {

namespace fs = std::filesystem;

constexpr int kTolerance = 12;  // per channel, 0..255 (rasterizer/driver noise)
constexpr double kMaxDifferingShare = 0.01;

fs::path baselineDir() { return fs::path(SAGRID_TEST_DATA_DIR) / "baselines"; }

void expectMatchesBaseline(const std::string& name, const RgbaImage& actual) {
  const fs::path expectedPath = baselineDir() / (name + ".png");
  const char* update = std::getenv("SAGRID_UPDATE_BASELINES");
  if (update && std::string(update) == "1") {
    writePng(expectedPath, actual);
    GTEST_SKIP() << "baseline regenerated: " << expectedPath;
  }
  const fs::path actualPath = baselineDir() / (name + ".actual.png");
  const fs::path diffPath = baselineDir() / (name + ".diff.png");
  if (!fs::exists(expectedPath)) {
    writePng(actualPath, actual);
    FAIL() << "no baseline " << expectedPath << "; actual written to " << actualPath
           << " (run with SAGRID_UPDATE_BASELINES=1 to accept it)";
  }
  const ImageDifference d = compareImages(readPng(expectedPath), actual, kTolerance);
  const bool ok = d.sameSize && d.differingShare <= kMaxDifferingShare;
  if (!ok) {
    writePng(actualPath, actual);
    if (d.sameSize) writePng(diffPath, d.diff);
  } else {
    fs::remove(actualPath);
    fs::remove(diffPath);
  }
  EXPECT_TRUE(ok) << name << ": " << (d.sameSize ? "" : "size differs; ") << d.differingPixels
                  << " pixels differ by more than " << kTolerance << " (share " << d.differingShare
                  << ", allowed " << kMaxDifferingShare << "); see " << actualPath << " and "
                  << diffPath;
}

TEST(RenderBaseline, SceneWithFieldAndPoints) {
  const auto dir = sagrid::test::freshTempDir();
  test::ScriptedApp s(dir, 320, 240);
  Session& session = s.app->session();
  session.view().field.visible = true;
  session.view().showGrid = true;
  session.camera().set({0, 0, 0.05f}, 2.2f, -1.0f, 0.6f);
  s.frame({});
  const RgbaImage image = s.app->capture();
  // Sanity before the baseline: the field's near colour (yellow) and the markers are in the image.
  int yellowish = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.at(x, y);
      if (p[0] > 180 && p[1] > 180 && p[2] < 90) ++yellowish;
    }
  }
  EXPECT_GT(yellowish, 20);
  expectMatchesBaseline("scene_field", image);
}

TEST(RenderBaseline, FullWindowWithPanels) {
  const auto dir = sagrid::test::freshTempDir();
  test::ScriptedApp s(dir, 800, 500);
  s.app->session().view().showPanels = true;
  s.app->session().view().field.visible = true;
  s.frame({});
  s.app->session().frameObject();
  s.frame({});
  expectMatchesBaseline("full_window", s.app->capture());
}

TEST(RenderBaseline, ComparisonDetectsAChangedImage) {
  RgbaImage a;
  a.width = 10, a.height = 10;
  a.pixels.assign(400, 100);
  RgbaImage b = a;
  b.at(3, 4)[1] = 200;
  const ImageDifference d = compareImages(a, b, kTolerance);
  EXPECT_EQ(d.differingPixels, 1u);
  EXPECT_DOUBLE_EQ(d.differingShare, 0.01);
  EXPECT_EQ(d.diff.at(3, 4)[0], 255);
  EXPECT_EQ(compareImages(a, a, 0).differingPixels, 0u);
}

}  // namespace
}  // namespace sagrid::ui
