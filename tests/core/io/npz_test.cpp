#include "core/io/npz.h"

#include <cstdlib>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

fs::path fixture() { return fs::path(SAGRID_TEST_DATA_DIR) / "numpy_compressed.npz"; }

NpzArchive sampleArchive() {
  NpzArchive archive;
  archive["coords"] = NpyArray::from(std::vector<std::int32_t>{1, 2, 3, 4, 5, 6}, {2, 3});
  archive["features"] = NpyArray::from(std::vector<float>{0.5f, -1.0f, 1e-7f, 3.25f}, {2, 2});
  archive["ids"] = NpyArray::from(std::vector<std::int64_t>{-5, 1LL << 40});
  archive["occupied"] = NpyArray::from(std::vector<std::uint8_t>{0, 1, 1, 0, 1, 0, 0, 1}, {2, 2, 2});
  archive["mask"] = NpyArray::from(std::vector<bool>{true, false, true});
  archive["scale"] = NpyArray::from(std::vector<double>{0.015625}, {});
  archive["empty"] = NpyArray::from(std::vector<float>{}, {0, 8});
  return archive;
}

TEST(Npz, ReadsDeflateCompressedFixtureWrittenLikeNumpy) {
  const NpzArchive archive = readNpz(fixture());
  ASSERT_EQ(archive.size(), 6u);
  const NpyArray& coords = archive.at("coords");
  EXPECT_EQ(coords.dtype, "int32");
  EXPECT_THAT(coords.shape, ElementsAre(4, 3));
  EXPECT_THAT(coords.as<std::int32_t>(), ElementsAre(0, 1, 2, 3, 4, 5, 6, 7, 8, 63, 0, 31));
  EXPECT_THAT(archive.at("features").as<float>(), ElementsAre(0.5f, -1.25f, 3.0f, 0.125f, 2.0f, -0.0f));
  EXPECT_TRUE(archive.at("resolution").shape.empty());
  EXPECT_THAT(archive.at("resolution").as<std::int64_t>(), ElementsAre(64));
  EXPECT_THAT(archive.at("mask").as<bool>(), ElementsAre(true, false, true));
  EXPECT_THAT(archive.at("grid").shape, ElementsAre(2, 2, 2));
  EXPECT_EQ(archive.at("grid").as<std::uint8_t>()[7], 7);
  EXPECT_THAT(archive.at("values").as<double>(), ElementsAre(3.141592653589793, -2.5));
  EXPECT_THAT(archive.at("coords").asDouble()[9], 63.0);
  EXPECT_THROW(coords.as<float>(), InvalidArgument);
}

TEST(Npz, WriteReadRoundTripAllDtypes) {
  const fs::path path = test::freshTempDir() / "a.npz";
  const NpzArchive written = sampleArchive();
  writeNpz(path, written);
  const NpzArchive read = readNpz(path);
  ASSERT_EQ(read.size(), written.size());
  for (const auto& [key, array] : written) {
    ASSERT_TRUE(read.count(key)) << key;
    EXPECT_EQ(read.at(key).dtype, array.dtype) << key;
    EXPECT_EQ(read.at(key).shape, array.shape) << key;
    EXPECT_EQ(read.at(key).data, array.data) << key;
  }
  EXPECT_THAT(read.at("ids").as<std::int64_t>(), ElementsAre(-5, 1LL << 40));
}

TEST(Npz, NpyHeaderIsNumpyCompatible) {
  const std::string bytes = serializeNpy(NpyArray::from(std::vector<float>{1, 2, 3}));
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t headerLength = static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
  EXPECT_EQ((10 + headerLength) % 64, 0u);
  const std::string header = bytes.substr(10, headerLength);
  EXPECT_THAT(header, HasSubstr("{'descr': '<f4', 'fortran_order': False, 'shape': (3,), }"));
  EXPECT_EQ(header.back(), '\n');
  EXPECT_EQ(bytes.size(), 10 + headerLength + 12);
  const fs::path path = test::freshTempDir() / "x.npy";
  writeNpy(path, NpyArray::from(std::vector<std::int32_t>{7, 8}, {1, 2}));
  EXPECT_THAT(readNpy(path).as<std::int32_t>(), ElementsAre(7, 8));
}

TEST(Npz, PythonReadsWhatWeWrite) {
  if (std::system("python3 -c 'import numpy' > /dev/null 2>&1") != 0) GTEST_SKIP() << "no numpy";
  const fs::path path = test::freshTempDir() / "a.npz";
  writeNpz(path, sampleArchive());
  const auto result = test::runCommand(
      "python3 -c \"import numpy as n; a = n.load('" + path.string() +
      "'); print(a['coords'].tolist(), a['mask'].tolist(), a['ids'].dtype, float(a['scale']), a['empty'].shape)\"");
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("[[1, 2, 3], [4, 5, 6]] [True, False, True] int64 0.015625 (0, 8)"));
}

TEST(Npz, PythonZipfileAcceptsOurArchive) {
  if (std::system("python3 -c 'import zipfile' > /dev/null 2>&1") != 0) GTEST_SKIP() << "no python3";
  const fs::path path = test::freshTempDir() / "a.npz";
  writeNpz(path, sampleArchive());
  const auto result = test::runCommand("python3 -c \"import zipfile; z = zipfile.ZipFile('" + path.string() +
                                       "'); print(z.testzip(), sorted(z.namelist())[:2])\"");
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("None ['coords.npy', 'empty.npy']"));
}

TEST(NpzErrors, CorruptFilesGiveFileErrors) {
  const fs::path dir = test::freshTempDir();
  auto errorOf = [&](const std::string& name, const std::string& bytes) -> std::string {
    const fs::path path = dir / name;
    std::ofstream(path, std::ios::binary) << bytes;
    try {
      readNpz(path);
    } catch (const FileError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path.string(), 0), 0u);
      return e.what();
    }
    return "no error";
  };
  const std::string good = readFileBytes(fixture());
  EXPECT_THAT(errorOf("short.npz", "PK"), HasSubstr("too short"));
  EXPECT_THAT(errorOf("text.npz", std::string(100, 'a')), HasSubstr("not a zip archive"));
  EXPECT_THAT(errorOf("cut.npz", good.substr(0, good.size() / 2)), HasSubstr("not a zip archive"));
  std::string flipped = good;
  flipped[120] ^= 0x55;  // inside the first entry's deflate data
  EXPECT_THAT(errorOf("flipped.npz", flipped), ::testing::AnyOf(HasSubstr("corrupt"), HasSubstr("npy")));
  EXPECT_THROW(readNpz(dir / "missing.npz"), FileError);

  // Bad .npy content inside an otherwise valid archive.
  NpzArchive archive;
  archive["a"] = NpyArray::from(std::vector<float>{1, 2, 3, 4});
  const fs::path written = dir / "w.npz";
  writeNpz(written, archive);
  std::string bytes = readFileBytes(written);
  const auto at = bytes.find("<f4");
  ASSERT_NE(at, std::string::npos);
  std::string bigEndian = bytes;
  bigEndian[at] = '>';  // the CRC no longer matches either; fix it up below by rewriting
  EXPECT_THAT(errorOf("crc.npz", bigEndian), HasSubstr("CRC mismatch"));
  std::string npy = serializeNpy(archive["a"]);
  npy.replace(npy.find("<f4"), 3, ">f4");
  EXPECT_THAT([&] {
    try { parseNpy(npy, "x.npy"); } catch (const FileError& e) { return std::string(e.what()); }
    return std::string();
  }(), HasSubstr("dtype '>f4' is not supported"));
  EXPECT_THAT([&] {
    try { parseNpy(serializeNpy(archive["a"]).substr(0, 130), "x.npy"); } catch (const FileError& e) { return std::string(e.what()); }
    return std::string();
  }(), HasSubstr("truncated"));
}

TEST(NpzErrors, WriteIsAtomicAndValidatesShape) {
  const fs::path dir = test::freshTempDir();
  EXPECT_THROW(NpyArray::from(std::vector<float>{1, 2, 3}, {2, 2}), InvalidArgument);
  NpzArchive bad;
  bad["x"].dtype = "float32";
  bad["x"].shape = {4};
  bad["x"].data.resize(3);  // wrong byte count
  EXPECT_THROW(writeNpz(dir / "bad.npz", bad), InvalidArgument);
  EXPECT_FALSE(fs::exists(dir / "bad.npz"));
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
// Issue 14: dimensions whose product wraps around 2^64 claimed a few bytes, then allocated
// everything when the array was used.
TEST(NpzErrors, ShapeProductIsCheckedBeforeItWraps) {
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (4294967296, 4294967296, 16), }";
  header += std::string(63 - (10 + header.size()) % 64, ' ') + "\n";
  std::string bytes("\x93NUMPY\x01\x00", 8);
  bytes += static_cast<char>(header.size() & 0xFF);
  bytes += static_cast<char>(header.size() >> 8);
  bytes += header + std::string(64, '\0');
  try {
    parseNpy(bytes, "wrap.npy");
    FAIL() << "accepted";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("npy shape claims more elements than the file holds"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace sagrid
