#include "core/features/texture_detail.h"

#include <gtest/gtest.h>

#include "core/features/feature_pipeline.h"
#include "core/grid/voxelize.h"
#include "core/mesh/mesh.h"

namespace sagrid {
namespace {

constexpr int kRes = 16;

// A flat textured square in the normalized frame (z = 0.01, x and y in [-0.45, 0.45]) whose
// texture is dark glass with one bright vertical line 2 texels wide at u = 0.5: thinner than a
// voxel (256 texels over 14.4 voxels).
Mesh glassWithLine(bool withLine) {
  Mesh mesh;
  mesh.positions = {{-0.45f, -0.45f, 0.01f}, {0.45f, -0.45f, 0.01f}, {0.45f, 0.45f, 0.01f},
                    {-0.45f, 0.45f, 0.01f}};
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  Texture t;
  t.width = t.height = 256;
  t.rgba.assign(256 * 256 * 4, 0);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const bool line = withLine && (x == 127 || x == 128);
      std::uint8_t* p = &t.rgba[static_cast<std::size_t>(y * 256 + x) * 4];
      p[0] = p[1] = p[2] = line ? 230 : 15;
      p[3] = 255;
    }
  mesh.textures.push_back(t);
  mesh.materials.push_back({"glass", Eigen::Vector3f::Ones(), 0});
  mesh.triangleMaterials = {0, 0};
  mesh.computeVertexNormals();
  return mesh;
}

TEST(TextureDetail, ALineThinnerThanAVoxelShowsOnlyInTheVoxelsItCrosses) {
  const Mesh mesh = glassWithLine(true);
  const VoxelGrid grid = voxelize(mesh, kRes);
  const auto detail = textureDetail(mesh, grid);
  const auto voxels = grid.occupiedVoxels();
  ASSERT_EQ(detail.size(), voxels.size() * kTextureDetailChannels);
  int lineVoxels = 0;
  for (std::size_t p = 0; p < voxels.size(); ++p) {
    const float x0 = static_cast<float>(voxels[p].i) / kRes - 0.5f, x1 = x0 + 1.0f / kRes;
    // The line's texels 127 and 128 span x = 0.9 (u - 0.5) in [-0.0035, 0.0035].
    const bool crossed = x0 < 0.0036f && -0.0036f < x1;
    const float variation = detail[p * kTextureDetailChannels];
    const float edges = detail[p * kTextureDetailChannels + 1];
    if (crossed) {
      ++lineVoxels;
      EXPECT_GT(variation, 0.1f) << p;
      EXPECT_GT(edges, 0.02f) << p;
    } else {
      EXPECT_LT(variation, 1e-3f) << p;
      EXPECT_LT(edges, 1e-3f) << p;
    }
  }
  EXPECT_GT(lineVoxels, 10);
  // The same glass without the line: nothing anywhere.
  const Mesh plain = glassWithLine(false);
  for (float v : textureDetail(plain, voxelize(plain, kRes))) EXPECT_LT(v, 1e-3f);
}

TEST(TextureDetail, EmbeddedTextureBackendAppendsTheTwoChannels) {
  FeatureOptions options;
  options.resolution = kRes;
  options.views = 24;
  options.renderSize = 48;
  const Mesh mesh = glassWithLine(true);
  const FeatureGrid plain = computeFeatures(mesh, options);
  options.backend = "embedded-texture";
  EXPECT_EQ(featureChannels(options), kEmbeddedChannels + kTextureDetailChannels);
  EXPECT_EQ(featureChannelNames(options).back(), "texture_edges");
  const FeatureGrid textured = computeFeatures(mesh, options);
  EXPECT_NE(textured.configHash, plain.configHash);
  EXPECT_EQ(textured.channels, kEmbeddedChannels + kTextureDetailChannels);
  ASSERT_EQ(textured.voxels, plain.voxels);
  EXPECT_EQ(textured.descriptor, plain.descriptor);
  const std::size_t wide = static_cast<std::size_t>(textured.channels);
  float strongest = 0;
  for (std::size_t p = 0; p < textured.voxels.size(); ++p) {
    for (int c = 0; c < kEmbeddedChannels; ++c)
      ASSERT_EQ(textured.values[p * wide + c], plain.values[p * kEmbeddedChannels + c]) << p;
    strongest = std::max(strongest, textured.values[p * wide + kEmbeddedChannels]);
  }
  EXPECT_GT(strongest, 0.1f);
}

}  // namespace
}  // namespace sagrid
