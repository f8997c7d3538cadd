#include "core/features/feature_pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/features/feature_cache.h"
#include "core/features/feature_npz.h"
#include "core/io/npz.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

FeatureOptions smallOptions() {
  FeatureOptions o;
  o.resolution = 16;
  o.views = 24;
  o.renderSize = 48;
  return o;
}

// A coloured box (OBJ with vertex colours) of 2 x 1 x 0.5 units.
std::filesystem::path writeBoxObj(const std::filesystem::path& dir, const std::string& extra = "") {
  const auto path = dir / "box.obj";
  std::ofstream out(path);
  for (int i = 0; i < 8; ++i) {
    out << "v " << (i & 1 ? 1.0 : -1.0) << " " << (i & 2 ? 0.5 : -0.5) << " " << (i & 4 ? 0.5 : 0.0)
        << " 0.8 0.3 0.1\n";
  }
  out << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n" << extra;
  return path;
}

TEST(FeaturePipeline, ChannelCountsAndNamesPerBackend) {
  FeatureOptions o;
  EXPECT_EQ(featureChannels(o), 16);
  EXPECT_EQ(descriptorSize(o), 64);
  EXPECT_EQ(featureChannelNames(o).front(), "albedo_r");
  o.backend = "dinov2";
  EXPECT_EQ(featureChannels(o), 1024);
  EXPECT_EQ(descriptorSize(o), 1024);
  o.backend = "trellis";
  EXPECT_EQ(featureChannels(o), 8);
  EXPECT_EQ(descriptorSize(o), 64);  // embedded descriptor without a DINOv2 model
  EXPECT_EQ(featureChannelNames(o)[7], "slat_7");
  o.backend = "clip";
  EXPECT_THROW(featureChannels(o), InvalidArgument);
}

TEST(FeaturePipeline, ConfigHashFollowsWhatChangesFeatures) {
  FeatureOptions a = smallOptions();
  FeatureOptions b = a;
  EXPECT_EQ(featureConfigHash(a), featureConfigHash(b));
  b.cacheDir = "/somewhere";
  EXPECT_EQ(featureConfigHash(a), featureConfigHash(b));  // where the cache is changes nothing
  b.views = 25;
  EXPECT_NE(featureConfigHash(a), featureConfigHash(b));
  b = a;
  b.aggregation = Aggregation::Mean;
  EXPECT_NE(featureConfigHash(a), featureConfigHash(b));
  b = a;
  b.resolution = 32;
  EXPECT_NE(featureConfigHash(a), featureConfigHash(b));
}

TEST(FeaturePipeline, ComputeFeaturesFillsTheContract) {
  Mesh mesh = test::box({-1.0f, -0.5f, 0.0f}, {1.0f, 0.5f, 0.5f});
  test::paint(mesh, {0.8f, 0.3f, 0.1f});
  const FeatureGrid g = computeFeatures(mesh, smallOptions());
  EXPECT_EQ(g.backend, "embedded");
  EXPECT_EQ(g.configHash, featureConfigHash(smallOptions()));
  EXPECT_EQ(g.resolution, 16);
  EXPECT_EQ(g.channels, 16);
  ASSERT_GT(g.voxels.size(), 100u);
  EXPECT_TRUE(std::is_sorted(g.voxels.begin(), g.voxels.end()));
  EXPECT_EQ(g.values.size(), g.voxels.size() * 16);
  EXPECT_EQ(g.descriptor.size(), 64u);
  EXPECT_NEAR(g.normalization.scale, 0.5f, 1e-6f);
  EXPECT_TRUE(g.normalization.center.isApprox(Eigen::Vector3f(0, 0, 0.25f)));
  // Same mesh, same features (seeded views).
  EXPECT_EQ(computeFeatures(mesh, smallOptions()).values, g.values);
  FeatureOptions bad = smallOptions();
  bad.backend = "dinov2";  // no model given
  EXPECT_THROW(computeFeatures(mesh, bad), InvalidArgument);
}

TEST(FeaturePipeline, CacheHitsMissesOnConfigChangeAndRebuildsDamagedEntries) {
  const auto dir = test::freshTempDir("feature_cache");
  const auto meshFile = writeBoxObj(dir);
  FeatureOptions o = smallOptions();
  o.cacheDir = dir / "cache";
  bool cached = true;
  const FeatureGrid first = extractFeatures(meshFile, o, &cached);
  EXPECT_FALSE(cached);
  const FeatureGrid second = extractFeatures(meshFile, o, &cached);
  EXPECT_TRUE(cached);
  EXPECT_EQ(second.values, first.values);
  EXPECT_EQ(second.descriptor, first.descriptor);
  EXPECT_EQ(second.normalization.center, first.normalization.center);

  // A config change is a different key: recomputed, not read.
  FeatureOptions changed = o;
  changed.views = 12;
  extractFeatures(meshFile, changed, &cached);
  EXPECT_FALSE(cached);
  extractFeatures(meshFile, changed, &cached);
  EXPECT_TRUE(cached);

  // A damaged entry (truncated) is rebuilt, with the right values, and then hits again.
  const std::string sha = sha256Hex(readFileBytes(meshFile));
  const auto entry = FeatureCache(o.cacheDir).entryPath(sha, featureConfigHash(o));
  ASSERT_TRUE(std::filesystem::exists(entry));
  const std::string bytes = readFileBytes(entry);
  writeFileAtomic(entry, bytes.substr(0, bytes.size() - 100));
  const FeatureGrid rebuilt = extractFeatures(meshFile, o, &cached);
  EXPECT_FALSE(cached);
  EXPECT_EQ(rebuilt.values, first.values);
  extractFeatures(meshFile, o, &cached);
  EXPECT_TRUE(cached);

  // Values edited inside a well-formed npz: checksum catches it, rebuilt.
  NpzArchive npz = readNpz(entry);
  std::vector<float> feats = npz.at("feats").as<float>();
  feats[0] += 1.0f;
  npz["feats"] = NpyArray::from(feats, npz.at("feats").shape);
  writeNpz(entry, npz);
  EXPECT_EQ(extractFeatures(meshFile, o, &cached).values, first.values);
  EXPECT_FALSE(cached);

  // The mesh file changes: new sha256, new entry.
  writeBoxObj(dir, "# edited\n");
  extractFeatures(meshFile, o, &cached);
  EXPECT_FALSE(cached);
}

TEST(FeaturePipeline, UpAxisOverrideIsCachedSeparately) {
  const auto dir = test::freshTempDir("feature_cache_up");
  const auto meshFile = writeBoxObj(dir);
  FeatureOptions o = smallOptions();
  o.cacheDir = dir / "cache";
  bool cached = true;
  const FeatureGrid z = extractFeatures(meshFile, o, &cached);
  o.up = UpAxis::Y;
  const FeatureGrid y = extractFeatures(meshFile, o, &cached);
  EXPECT_FALSE(cached);
  EXPECT_NE(y.voxels.size(), 0u);
  EXPECT_NE(y.normalization.center, z.normalization.center);  // (0, 0, 0.25) vs (0, -0.25, 0)
}

TEST(FeaturePipeline, TrellisBackendTakesVoxelsAndLatentsFromTheTrellisFile) {
  const auto dir = test::freshTempDir("feature_trellis");
  const auto meshFile = writeBoxObj(dir);
  const std::string sha = sha256Hex(readFileBytes(meshFile));
  std::filesystem::create_directories(dir / "latents");
  const std::vector<std::uint8_t> coords{63, 10, 5, 0, 20, 30};
  std::vector<float> feats(16);
  for (int i = 0; i < 16; ++i) feats[i] = 0.5f * i;
  writeNpz(dir / "latents" / (sha + ".npz"),
           {{"coords", NpyArray::from(coords, {2, 3})}, {"feats", NpyArray::from(feats, {2, 8})}});
  FeatureOptions o;
  o.backend = "trellis";
  o.trellisLatents = dir / "latents";
  o.views = 12;
  const FeatureGrid g = extractFeatures(meshFile, o);
  EXPECT_EQ(g.backend, "trellis");
  EXPECT_EQ(g.channels, 8);
  ASSERT_EQ(g.voxels.size(), 2u);
  EXPECT_EQ(g.voxels[0], (VoxelIndex{0, 20, 30}));
  EXPECT_EQ(g.values[0], 4.0f);         // second file row first after sorting
  EXPECT_EQ(g.descriptor.size(), 64u);  // embedded descriptor: no DINOv2 model given
  // No latent for this mesh: the error names the expected file.
  writeBoxObj(dir, "# another mesh\n");
  try {
    extractFeatures(meshFile, o);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(".npz"), std::string::npos);
  }
  o.resolution = 32;
  EXPECT_THROW(extractFeatures(meshFile, o), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
