#include "core/features/feature_npz.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/io/npz.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

FeatureGrid sampleGrid() {
  FeatureGrid g;
  g.backend = "embedded";
  g.configHash = "0123456789abcdef";
  g.resolution = 64;
  g.channels = 3;
  g.voxels = {{0, 1, 2}, {5, 6, 7}, {63, 0, 31}};
  g.values = {0.f, 1.f, 2.f, 3.5f, -4.f, 5.f, 6.f, 7.f, 1e-7f};
  g.descriptor = {0.25f, 0.5f, 0.125f, 1.f};
  g.normalization.center = Eigen::Vector3f(1.f, -2.f, 0.5f);
  g.normalization.scale = 3.25f;
  return g;
}

TEST(FeatureNpz, RoundTripKeepsEverything) {
  const auto path = test::freshTempDir("npz_roundtrip") / "f.npz";
  const FeatureGrid g = sampleGrid();
  writeFeatureNpz(path, g, {{"id", "obj1"}});
  nlohmann::json meta;
  const FeatureGrid back = readFeatureNpz(path, &meta);
  EXPECT_EQ(back.backend, g.backend);
  EXPECT_EQ(back.configHash, g.configHash);
  EXPECT_EQ(back.resolution, 64);
  EXPECT_EQ(back.channels, 3);
  EXPECT_EQ(back.voxels, g.voxels);
  EXPECT_EQ(back.values, g.values);
  EXPECT_EQ(back.descriptor, g.descriptor);
  EXPECT_EQ(back.normalization.center, g.normalization.center);
  EXPECT_EQ(back.normalization.scale, g.normalization.scale);
  EXPECT_EQ(meta["id"], "obj1");
  EXPECT_EQ(meta["schema"], kFeatureNpzSchema);
}

TEST(FeatureNpz, LayoutIsWhatPythonToolsExpect) {
  // numpy.load(path): coords int32 (N, 3), feats float32 (N, C), descriptor float32 (D,),
  // normalization_scale a 0-d float32, metadata uint8 bytes of JSON.
  const auto path = test::freshTempDir("npz_layout") / "f.npz";
  writeFeatureNpz(path, sampleGrid());
  const NpzArchive npz = readNpz(path);
  EXPECT_EQ(npz.at("coords").dtype, "int32");
  EXPECT_EQ(npz.at("coords").shape, (std::vector<std::size_t>{3, 3}));
  EXPECT_EQ(npz.at("coords").as<std::int32_t>()[3], 5);  // row-major (i, j, k) per voxel
  EXPECT_EQ(npz.at("feats").dtype, "float32");
  EXPECT_EQ(npz.at("feats").shape, (std::vector<std::size_t>{3, 3}));
  EXPECT_EQ(npz.at("descriptor").shape, (std::vector<std::size_t>{4}));
  EXPECT_TRUE(npz.at("normalization_scale").shape.empty());
  EXPECT_EQ(npz.at("normalization_center").shape, (std::vector<std::size_t>{3}));
  const auto& meta = npz.at("metadata");
  EXPECT_EQ(meta.dtype, "uint8");
  const auto json = nlohmann::json::parse(meta.data.begin(), meta.data.end());
  EXPECT_EQ(json["channels"], 3);
  EXPECT_EQ(json["checksum"].get<std::string>().size(), 64u);
}

TEST(FeatureNpz, DamagedFilesAreRefusedWithTheirPath) {
  const auto dir = test::freshTempDir("npz_damaged");
  const auto path = dir / "f.npz";
  writeFeatureNpz(path, sampleGrid());
  // Values changed behind the checksum's back (a valid npz with the old metadata).
  NpzArchive npz = readNpz(path);
  std::vector<float> feats = npz.at("feats").as<float>();
  feats[4] = 99.0f;
  npz["feats"] = NpyArray::from(feats, {3, 3});
  writeNpz(dir / "tampered.npz", npz);
  try {
    readFeatureNpz(dir / "tampered.npz");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("tampered.npz"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos);
  }
  // Wrong dtype.
  npz = readNpz(path);
  npz["coords"] = NpyArray::from(std::vector<std::int64_t>(9, 1), {3, 3});
  writeNpz(dir / "dtype.npz", npz);
  EXPECT_THROW(readFeatureNpz(dir / "dtype.npz"), FileError);
  // Truncated file.
  const std::string bytes = readFileBytes(path);
  writeFileAtomic(dir / "truncated.npz", bytes.substr(0, bytes.size() / 2));
  EXPECT_THROW(readFeatureNpz(dir / "truncated.npz"), FileError);
  // Not a zip at all, and missing.
  writeFileAtomic(dir / "junk.npz", "hello");
  EXPECT_THROW(readFeatureNpz(dir / "junk.npz"), FileError);
  EXPECT_THROW(readFeatureNpz(dir / "missing.npz"), FileError);
}

// Issue 14: a cached feature file with scale 0 or NaN and a recomputed checksum gave labels with
// [null, null, null] positions; the numbers are validated on load.
TEST(FeatureNpz, UnusableNormalizationIsRefusedEvenWithAValidChecksum) {
  const auto dir = test::freshTempDir("npz_scale");
  const float scales[] = {0.0f, std::nanf(""), -1.0f, INFINITY};
  for (float scale : scales) {
    FeatureGrid g = sampleGrid();
    g.normalization.scale = scale;
    writeFeatureNpz(dir / "f.npz", g);  // the checksum covers the bad scale
    try {
      readFeatureNpz(dir / "f.npz");
      FAIL() << "scale " << scale << " accepted";
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find("normalization scale is"), std::string::npos) << e.what();
    }
  }
  FeatureGrid g = sampleGrid();
  g.values[2] = std::nanf("");
  writeFeatureNpz(dir / "values.npz", g);
  EXPECT_THROW(readFeatureNpz(dir / "values.npz"), FileError);
}

}  // namespace
}  // namespace sagrid
