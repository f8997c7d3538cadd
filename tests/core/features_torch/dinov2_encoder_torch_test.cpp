// The dinov2 backend end to end with stand-in TorchScript models built here in C++ with the same
// contract as the exported dinov2_vitl14_reg: forward(x [B, 3, S, S]) -> [B, (S/14)^2, C]. The
// stand-in returns each patch's mean normalized colour (repeated over channels, scaled by
// channel group), so expected values are computable from the rendered images.
#include <gtest/gtest.h>
#include <torch/script.h>
#include <torch/torch.h>

#include <cmath>
#include <fstream>

#include "core/common/error.h"
#include "core/features/dinov2_encoder.h"
#include "core/features/feature_pipeline.h"
#include "core/geometry/surface_scene.h"
#include "core/render/multiview_renderer.h"
#include "core/render/trellis_views.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

// Patch-mean model: token (y * g + x), channel c = (c / 3 + 1) * mean of colour (c % 3) over the
// 14x14 patch at column x, row y.
std::filesystem::path savePatchMeanModel(const std::filesystem::path& dir, int channels) {
  torch::jit::Module m("PatchMean");
  m.register_buffer("scale", (torch::arange(channels, torch::kFloat32).floor_divide(3) + 1));
  m.define(R"(
def forward(self, x):
    b = x.size(0)
    g = x.size(2) // 14
    p = x.reshape([b, 3, g, 14, g, 14]).mean([3, 5])
    t = p.flatten(2).transpose(1, 2)
    reps = (self.scale.size(0) + 2) // 3
    return t.repeat([1, 1, reps])[:, :, :self.scale.size(0)] * self.scale
)");
  const auto path = dir / "patch_mean.pt";
  m.save(path.string());
  return path;
}

std::filesystem::path saveWrongShapeModel(const std::filesystem::path& dir) {
  torch::jit::Module m("WrongShape");
  m.define(R"(
def forward(self, x):
    return x.flatten(2)
)");
  const auto path = dir / "wrong_shape.pt";
  m.save(path.string());
  return path;
}

std::filesystem::path saveTupleModel(const std::filesystem::path& dir) {
  torch::jit::Module m("Tuple");
  m.define(R"(
def forward(self, x):
    return (x, x)
)");
  const auto path = dir / "tuple.pt";
  m.save(path.string());
  return path;
}

Mesh colouredSphere() {
  Mesh mesh = test::uvSphere(Eigen::Vector3f::Zero(), 0.45f, 24);
  test::paint(mesh, {0.9f, 0.5f, 0.1f});
  mesh.sha256 = "feedface";
  return mesh;
}

TEST(Dinov2Encoder, PreprocessesAndLaysOutPatchTokensAsTrellis) {
  const auto dir = test::freshTempDir("dinov2_layout");
  Dinov2Encoder encoder(savePatchMeanModel(dir, 1024));  // full 518 -> 37x37x1024 contract
  ASSERT_EQ(encoder.patchGrid(), 37);
  const Mesh mesh = colouredSphere();
  const SurfaceScene scene(mesh);
  const MultiViewRenderer renderer(mesh, scene);
  const ViewCamera cam = ViewCamera::lookAtOrigin(0.4f, 0.2f, 2.0f, 40.0f / 180.0f * M_PI);
  const RenderedView view = renderer.render(cam, 518);
  std::vector<FeatureMap> maps;
  encoder.encode({&view}, {&cam}, maps);
  ASSERT_EQ(maps.size(), 1u);
  ASSERT_EQ(maps[0].width, 37);
  ASSERT_EQ(maps[0].channels, 1024);
  // Check a background patch, a centre patch and an off-centre one against the image.
  for (const auto& [px, py] : std::vector<std::pair<int, int>>{{0, 0}, {18, 18}, {12, 22}}) {
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (int y = py * 14; y < py * 14 + 14; ++y)
        for (int x = px * 14; x < px * 14 + 14; ++x)
          sum += (view.rgb[(static_cast<std::size_t>(y) * 518 + x) * 3 + c] - kImageNetMean[c]) /
                 kImageNetStd[c];
      const float expected = static_cast<float>(sum / 196);
      EXPECT_NEAR(maps[0].at(px, py)[c], expected, 1e-4f) << px << "," << py;
      EXPECT_NEAR(maps[0].at(px, py)[c + 3], 2 * expected, 2e-4f);
      EXPECT_NEAR(maps[0].at(px, py)[1023], 342 * maps[0].at(px, py)[0], 1e-2f);
    }
  }
  // The black background normalizes to -mean/std.
  EXPECT_NEAR(maps[0].at(0, 0)[0], -kImageNetMean[0] / kImageNetStd[0], 1e-5f);
}

TEST(Dinov2Encoder, WrongOutputShapeIsAModelError) {
  const auto dir = test::freshTempDir("dinov2_wrong");
  const Mesh mesh = colouredSphere();
  const SurfaceScene scene(mesh);
  const RenderedView view =
      MultiViewRenderer(mesh, scene).render(ViewCamera::lookAtOrigin(0, 0, 2, 0.7f), 28);
  const ViewCamera cam;
  std::vector<FeatureMap> maps;
  for (const auto& file : {saveWrongShapeModel(dir), saveTupleModel(dir)}) {
    Dinov2Encoder encoder(file, 28, 1024);
    try {
      encoder.encode({&view}, {&cam}, maps);
      FAIL() << "expected ModelError for " << file;
    } catch (const ModelError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("[1, 4, 1024]"), std::string::npos) << e.what();
    }
  }
  // Right shape but another channel count (e.g. a ViT-B export, 768).
  Dinov2Encoder vitB(savePatchMeanModel(dir, 768), 28, 1024);
  EXPECT_THROW(vitB.encode({&view}, {&cam}, maps), ModelError);
}

TEST(Dinov2Encoder, MissingOrCorruptModelFileIsAFileError) {
  const auto dir = test::freshTempDir("dinov2_corrupt");
  EXPECT_THROW(Dinov2Encoder(dir / "none.pt"), FileError);
  std::ofstream(dir / "junk.pt") << "not a zip";
  EXPECT_THROW(Dinov2Encoder(dir / "junk.pt"), FileError);
}

TEST(Dinov2Backend, ComputeFeaturesAggregatesPatchTokensIntoVoxels) {
  const auto dir = test::freshTempDir("dinov2_backend");
  FeatureOptions options;
  options.backend = "dinov2";
  options.dinov2Model = savePatchMeanModel(dir, 1024);
  options.resolution = 16;
  options.views = 6;
  options.renderSize = 56;  // 4x4 patches keep the test fast; 518 is the default
  EXPECT_EQ(featureChannels(options), 1024);
  EXPECT_EQ(descriptorSize(options), 1024);
  const Mesh mesh = colouredSphere();
  const FeatureGrid grid = computeFeatures(mesh, options);
  EXPECT_EQ(grid.backend, "dinov2");
  EXPECT_EQ(grid.channels, 1024);
  ASSERT_GT(grid.voxels.size(), 100u);
  ASSERT_EQ(grid.values.size(), grid.voxels.size() * 1024);
  ASSERT_EQ(grid.descriptor.size(), 1024u);
  // Every voxel's channel c+3 is twice channel c (the stand-in's channel scale survives
  // bilinear sampling and averaging), and values lie between background and full colour.
  const float background = -kImageNetMean[0] / kImageNetStd[0];
  const float orange = (0.9f - kImageNetMean[0]) / kImageNetStd[0];
  for (std::size_t v = 0; v < grid.voxels.size(); ++v) {
    const float* f = grid.featuresOf(v);
    EXPECT_NEAR(f[3], 2 * f[0], 1e-3f);
    EXPECT_GE(f[0], background - 1e-3f);
    EXPECT_LE(f[0], orange + 1e-3f);
  }
  // Descriptor: coverage-weighted mean token; red channel above background (object is orange).
  EXPECT_GT(grid.descriptor[0], background + 0.5f);
  EXPECT_NEAR(grid.descriptor[5], 2 * grid.descriptor[2], 1e-3f);
  // Mismatched model through the pipeline: ModelError, not a crash.
  options.dinov2Model = saveWrongShapeModel(dir);
  EXPECT_THROW(computeFeatures(mesh, options), ModelError);
}

}  // namespace
}  // namespace sagrid
