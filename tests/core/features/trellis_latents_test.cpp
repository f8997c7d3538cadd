#include "core/features/trellis_latents.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/npz.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

// A latent file as TRELLIS's encode_latent.py writes it: coords uint8 (N, 3), feats float32 (N, 8).
NpzArchive trellisNpz(const std::vector<std::uint8_t>& coords, int channels = 8) {
  const std::size_t n = coords.size() / 3;
  std::vector<float> feats(n * channels);
  for (std::size_t i = 0; i < feats.size(); ++i) feats[i] = static_cast<float>(i);
  return {{"coords", NpyArray::from(coords, {n, 3})},
          {"feats", NpyArray::from(feats, {n, static_cast<std::size_t>(channels)})}};
}

std::string errorOf(const std::filesystem::path& path) {
  try {
    readTrellisLatents(path);
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

TEST(TrellisLatents, ReadsTrellisFilesAndSortsVoxelsWithTheirRows) {
  const auto dir = test::freshTempDir("trellis_ok");
  writeNpz(dir / "abc.npz", trellisNpz({63, 0, 1, /**/ 0, 2, 3, /**/ 10, 40, 5}));
  const TrellisLatents l = readTrellisLatents(trellisLatentFile(dir, "abc"));
  ASSERT_EQ(l.channels, 8);
  ASSERT_EQ(l.voxels.size(), 3u);
  EXPECT_EQ(l.voxels[0], (VoxelIndex{0, 2, 3}));
  EXPECT_EQ(l.voxels[2], (VoxelIndex{63, 0, 1}));
  EXPECT_EQ(l.feats[0], 8.0f);   // row 1 of the file moved first
  EXPECT_EQ(l.feats[16], 0.0f);  // row 0 of the file is last
  EXPECT_EQ(l.feats[8], 16.0f);
  EXPECT_THROW(trellisLatentFile(dir, "nothere"), FileError);
}

TEST(TrellisLatents, BadFilesGetClearErrors) {
  const auto dir = test::freshTempDir("trellis_bad");
  // 32^3 grid: every coordinate below 32.
  writeNpz(dir / "grid32.npz", trellisNpz({0, 0, 0, 31, 20, 10}));
  EXPECT_NE(errorOf(dir / "grid32.npz").find("64^3"), std::string::npos)
      << errorOf(dir / "grid32.npz");
  // Coordinates beyond the grid.
  NpzArchive big = trellisNpz({0, 0, 0});
  big["coords"] = NpyArray::from(std::vector<std::int32_t>{0, 0, 70}, {1, 3});
  writeNpz(dir / "big.npz", big);
  EXPECT_NE(errorOf(dir / "big.npz").find("outside"), std::string::npos);
  // Float coordinates and float64 feats: wrong dtypes, named.
  NpzArchive floatCoords = trellisNpz({0, 0, 63});
  floatCoords["coords"] = NpyArray::from(std::vector<float>{0, 0, 63}, {1, 3});
  writeNpz(dir / "fc.npz", floatCoords);
  EXPECT_NE(errorOf(dir / "fc.npz").find("float32"), std::string::npos);
  NpzArchive doubleFeats = trellisNpz({0, 0, 63});
  doubleFeats["feats"] = NpyArray::from(std::vector<double>(8, 0.0), {1, 8});
  writeNpz(dir / "df.npz", doubleFeats);
  EXPECT_NE(errorOf(dir / "df.npz").find("float64"), std::string::npos);
  // Mismatched rows, duplicates, missing keys.
  NpzArchive rows = trellisNpz({0, 0, 63, 1, 1, 1});
  rows["feats"] = NpyArray::from(std::vector<float>(8, 0.f), {1, 8});
  writeNpz(dir / "rows.npz", rows);
  EXPECT_NE(errorOf(dir / "rows.npz").find("one row per voxel"), std::string::npos);
  writeNpz(dir / "dup.npz", trellisNpz({0, 0, 63, 0, 0, 63}));
  EXPECT_NE(errorOf(dir / "dup.npz").find("twice"), std::string::npos);
  writeNpz(dir / "nokeys.npz", {{"x", NpyArray::from(std::vector<float>{1})}});
  EXPECT_NE(errorOf(dir / "nokeys.npz").find("coords"), std::string::npos);
}

}  // namespace
}  // namespace sagrid
