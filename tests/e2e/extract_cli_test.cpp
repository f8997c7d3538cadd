// End-to-end: `sagrid extract` as a user runs it: a folder of real meshes with a cache (second
// run served from it), the .npz output, TRELLIS-layout view export, and bad input (one clear
// line, non-zero exit).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/features/feature_npz.h"
#include "core/mesh/mesh_export.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::runSagrid;
using test::shellQuote;
using ::testing::HasSubstr;

TEST(ExtractCommand, FolderWithCacheAndOutputs) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP();
  const fs::path dir = test::freshTempDir("extract_cli");
  const std::string common = shellQuote(test::realDevDir().string()) + " --out " +
                             shellQuote((dir / "out").string()) + " --cache " +
                             shellQuote((dir / "cache").string()) + " --views 16 --resolution 32";
  auto r = runSagrid("extract " + common);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("3 of 3 meshes"));
  EXPECT_THAT(r.output, HasSubstr("(0 from cache)"));
  EXPECT_THAT(r.output, HasSubstr("3/3"));  // progress bar on stderr
  r = runSagrid("extract " + common);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("(3 from cache)"));
  nlohmann::json meta;
  const FeatureGrid g = readFeatureNpz(dir / "out" / "libero__flat_stove.npz", &meta);
  EXPECT_EQ(g.resolution, 32);
  EXPECT_EQ(g.channels, 16);
  EXPECT_EQ(meta["id"], "libero__flat_stove");
  EXPECT_GT(g.voxels.size(), 500u);
}

TEST(ExtractCommand, ReadsAnObjInTheFrameOfItsDetectedUpAxisLikeAnnotate) {
  const fs::path dir = test::freshTempDir("extract_cli_up");
  // A counter-like slab written y-up: wide in x and z (the file's floor plane), low in y.
  const fs::path file = dir / "slab_yup.obj";
  exportMesh(test::box({-1, 0, -0.5f}, {1, 0.3f, 0.5f}), file);
  const std::string common = shellQuote(file.string()) + " --resolution 32 --views 4 --out ";
  auto r = runSagrid("extract " + common + shellQuote((dir / "detected").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  r = runSagrid("extract " + common + shellQuote((dir / "given").string()) + " --up y");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  r = runSagrid("extract " + common + shellQuote((dir / "zup").string()) + " --up z");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  nlohmann::json meta, givenMeta;
  const FeatureGrid detected = readFeatureNpz(dir / "detected" / "slab_yup.npz", &meta);
  const FeatureGrid given = readFeatureNpz(dir / "given" / "slab_yup.npz", &givenMeta);
  const FeatureGrid zUp = readFeatureNpz(dir / "zup" / "slab_yup.npz");
  EXPECT_EQ(meta["up"], "y");
  EXPECT_TRUE(meta.contains("up_confidence"));
  EXPECT_EQ(givenMeta["up"], "y");
  EXPECT_FALSE(givenMeta.contains("up_confidence"));  // given, not detected
  EXPECT_EQ(detected.voxels, given.voxels);
  EXPECT_EQ(detected.descriptor, given.descriptor);
  EXPECT_NE(detected.voxels, zUp.voxels);  // the frames differ, so the test tells them apart
}

TEST(ExtractCommand, ExportsViewsInTrellisLayout) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP();
  const fs::path dir = test::freshTempDir("extract_views");
  const fs::path mesh = test::realDevDir() / "libero__faucet_knob" / "mesh.obj";
  const auto r = runSagrid(
      "extract " + shellQuote(mesh.string()) + " --out " + shellQuote((dir / "out").string()) +
      " --views 3 --render-size 64 --export-views " + shellQuote((dir / "views").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path views = dir / "views" / "libero__faucet_knob";
  EXPECT_TRUE(fs::exists(views / "000.png"));
  EXPECT_TRUE(fs::exists(views / "002_depth.png"));
  const auto transforms = nlohmann::json::parse(
      test::runCommand("cat " + shellQuote((views / "transforms.json").string())).output);
  ASSERT_EQ(transforms["frames"].size(), 3u);
  EXPECT_NEAR(transforms["frames"][0]["camera_angle_x"].get<double>(), 40.0 / 180.0 * M_PI, 1e-6);
}

TEST(ExtractCommand, BadInputGivesOneClearError) {
  const fs::path dir = test::freshTempDir("extract_bad");
  auto r = runSagrid("extract " + shellQuote((dir / "nothing.obj").string()) + " --out " +
                     shellQuote(dir.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_THAT(r.output, HasSubstr("nothing.obj: no such file"));
  r = runSagrid("extract " + shellQuote(dir.string()) + " --out " + shellQuote(dir.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_THAT(r.output, HasSubstr("no mesh files found"));
  if (fs::exists(test::realDevDir())) {
    r = runSagrid("extract " + shellQuote(test::realDevDir().string()) +
                  " --backend dinov2 --out " + shellQuote(dir.string()));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.output, HasSubstr("--dinov2-model"));
  }
}

}  // namespace
}  // namespace sagrid
