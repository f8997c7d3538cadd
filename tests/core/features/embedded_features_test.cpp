#include "core/features/embedded_features.h"

#include <gtest/gtest.h>

#include <numeric>

#include "core/geometry/surface_scene.h"
#include "core/grid/voxelize.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

using namespace embedded;

struct Computed {
  VoxelGrid grid;
  std::vector<VoxelIndex> voxels;
  Result result;
  const float* at(std::size_t i) const { return &result.values[i * kChannelCount]; }
};

Computed run(const Mesh& mesh, int res, Aggregation aggregation = Aggregation::OcclusionAware) {
  Computed c{voxelize(mesh, res), {}, {}};
  c.voxels = c.grid.occupiedVoxels();
  const SurfaceScene scene(mesh);
  Settings s;
  s.views = 60;
  s.renderSize = 64;
  s.aggregation = aggregation;
  c.result = compute(mesh, scene, c.grid, 1234, s);
  return c;
}

// Box [-0.4, 0.4] x [-0.3, 0.3] x [-0.2, 0.2] (already normalized-frame sized), painted.
Mesh paintedBox() {
  Mesh box = test::box({-0.4f, -0.3f, -0.2f}, {0.4f, 0.3f, 0.2f});
  test::paint(box, {0.2f, 0.6f, 0.9f});
  return box;
}

TEST(EmbeddedFeatures, TheThreadCountDoesNotChangeOneBit) {
  // Issue 42: per-thread partial sums merged at the end differed in the last bits between
  // thread counts, and a near-tie between field minima turned that into a point on another part.
  const Mesh mesh = paintedBox();
  const VoxelGrid grid = voxelize(mesh, 32);
  const SurfaceScene scene(mesh);
  Settings s;
  s.views = 37;  // not a multiple of any batch
  s.renderSize = 48;
  s.threads = 1;
  const Result one = compute(mesh, scene, grid, 99, s);
  ASSERT_FALSE(one.values.empty());
  for (int threads : {2, 3, 8}) {
    s.threads = threads;
    const Result more = compute(mesh, scene, grid, 99, s);
    EXPECT_EQ(more.values, one.values) << threads << " threads";
    EXPECT_EQ(more.descriptor, one.descriptor) << threads << " threads";
  }
}

TEST(EmbeddedFeatures, BoxFacesGetTheirNormalsHeightsAndVisibility) {
  const int res = 16;
  const Computed c = run(paintedBox(), res);
  ASSERT_EQ(c.result.values.size(), c.voxels.size() * kChannelCount);
  int top = 0, bottom = 0;
  for (std::size_t i = 0; i < c.voxels.size(); ++i) {
    const VoxelIndex& v = c.voxels[i];
    const float* f = c.at(i);
    for (int ch = 0; ch < kChannelCount; ++ch) {
      ASSERT_TRUE(std::isfinite(f[ch]));
      ASSERT_GE(f[ch], -1.0f - 1e-5f);
      ASSERT_LE(f[ch], 1.0f + 1e-5f);
    }
    EXPECT_NEAR(f[kAlbedoR], 0.2f, 0.02f);
    EXPECT_NEAR(f[kAlbedoB], 0.9f, 0.02f);
    const bool interiorOfFace = v.i > 3 && v.i < 12 && v.j > 4 && v.j < 11;
    // z = 0.2 lies on the face between voxel layers k = 12 and 13 (0.2 * 16 + 8 = 11.2 -> k 11).
    const Eigen::Vector3f centre = voxelCenter(v, res);
    if (interiorOfFace && centre.z() > 0.15f) {
      ++top;
      EXPECT_GT(f[kNormalZ], 0.99f);
      EXPECT_FLOAT_EQ(f[kHeight], 1.0f);
      EXPECT_GT(f[kTopVisibility], 0.6f);  // seen from most views above
      EXPECT_GT(f[kVisibility], 0.3f);
      EXPECT_LT(f[kVisibility], 0.7f);                // ...and none below
      EXPECT_NEAR(f[kOccupancy3], 8.0f / 26, 1e-6f);  // a flat sheet of voxels
      EXPECT_NEAR(f[kNormalVariation], 0.0f, 1e-4f);
      EXPECT_NEAR(f[kAreaDensity], std::log(2.0f) / std::log(5.0f), 0.05f);  // one voxel face
      EXPECT_NEAR(f[kLuminanceContrast], 0.0f, 0.02f);
    }
    if (interiorOfFace && centre.z() < -0.15f) {
      ++bottom;
      EXPECT_LT(f[kNormalZ], -0.99f);
      EXPECT_FLOAT_EQ(f[kHeight], 0.0f);
      EXPECT_LT(f[kTopVisibility], 0.05f);  // only grazing views past the bottom edge
    }
    // Voxels on box edges see normals of two faces.
    const bool edge = v.i == c.voxels.front().i && v.k == 11;  // x = -0.4 and z = 0.2 meet
    if (edge && v.j > 4 && v.j < 11) {
      EXPECT_GT(f[kNormalVariation], 0.3f);
    }
  }
  EXPECT_GT(top, 20);
  EXPECT_GT(bottom, 20);
}

TEST(EmbeddedFeatures, HiddenInnerSurfaceIsInvisibleAndKeepsItsOwnColour) {
  // A red cube inside the blue box: never seen from outside. Occlusion-aware aggregation gives
  // it zero visibility and its own (surface-sampled) albedo; TRELLIS's plain mean would paint it
  // with the box's colour.
  Mesh mesh = paintedBox();
  Mesh inner = test::box({-0.1f, -0.1f, -0.1f}, {0.1f, 0.1f, 0.1f});
  test::paint(inner, {1.0f, 0.0f, 0.0f});
  test::append(mesh, inner);
  const int res = 16;
  const Computed occ = run(mesh, res);
  const Computed mean = run(mesh, res, Aggregation::Mean);
  int innerVoxels = 0;
  for (std::size_t i = 0; i < occ.voxels.size(); ++i) {
    const Eigen::Vector3f c = voxelCenter(occ.voxels[i], res);
    if (c.cwiseAbs().maxCoeff() > 0.15f) continue;
    ++innerVoxels;
    EXPECT_EQ(occ.at(i)[kVisibility], 0.0f);
    EXPECT_NEAR(occ.at(i)[kAlbedoR], 1.0f, 1e-3f);
    EXPECT_NEAR(occ.at(i)[kAlbedoB], 0.0f, 1e-3f);
    EXPECT_GT(mean.at(i)[kVisibility], 0.9f);  // every view projects it onto the box
    EXPECT_NEAR(mean.at(i)[kAlbedoB], 0.9f, 0.05f);
  }
  EXPECT_GT(innerVoxels, 20);
}

TEST(EmbeddedFeatures, MeshWithoutUvsFallsBackToMaterialColour) {
  // A textured material but no texture coordinates: the documented fallback is the material's
  // base colour (the texture is ignored), never a crash.
  Mesh mesh = test::box({-0.4f, -0.3f, -0.2f}, {0.4f, 0.3f, 0.2f});
  Texture tex;
  tex.width = tex.height = 2;
  tex.rgba.assign(16, 0);  // black texture: would make everything black if used
  mesh.textures.push_back(tex);
  mesh.materials.push_back({"painted", {0.3f, 0.7f, 0.1f}, 0});
  mesh.triangleMaterials.assign(mesh.triangles.size(), 0);
  ASSERT_TRUE(mesh.uvs.empty());
  const Computed c = run(mesh, 8);
  for (std::size_t i = 0; i < c.voxels.size(); ++i) {
    EXPECT_NEAR(c.at(i)[kAlbedoR], 0.3f, 0.02f);
    EXPECT_NEAR(c.at(i)[kAlbedoG], 0.7f, 0.02f);
  }
}

TEST(EmbeddedFeatures, DescriptorHasFixedLayoutAndNormalizedHistograms) {
  const Computed c = run(paintedBox(), 16);
  ASSERT_EQ(c.result.descriptor.size(), static_cast<std::size_t>(kEmbeddedDescriptorSize));
  for (int h = 0; h < 7; ++h) {
    const float sum = std::accumulate(c.result.descriptor.begin() + h * kHistogramBins,
                                      c.result.descriptor.begin() + (h + 1) * kHistogramBins, 0.0f);
    EXPECT_NEAR(sum, 1.0f, 1e-5f) << "histogram " << h;
  }
  const float* tail = c.result.descriptor.data() + 7 * kHistogramBins;
  EXPECT_NEAR(tail[0], 1.0f, 1e-5f);         // longer horizontal extent / largest
  EXPECT_NEAR(tail[1], 0.6f / 0.8f, 1e-4f);  // shorter horizontal
  EXPECT_NEAR(tail[2], 0.4f / 0.8f, 1e-4f);  // vertical
  EXPECT_NEAR(tail[4], 0.2f, 0.02f);         // mean albedo r
  EXPECT_EQ(channelNames().size(), static_cast<std::size_t>(kEmbeddedChannels));
}

}  // namespace
}  // namespace sagrid
