// Crafted ZIP/zip64 archives (issue 14): offsets and sizes from the file are checked before they
// are used, without wrapping around. The first case is the one valgrind found: zip64 entries whose
// local-header offset is 2^64 - 13 made readNpz read 13-16 bytes before its buffer (the check
// `offset + 30 > size` wrapped to 17). Run under `make test-asan`, each case read outside the
// buffer or allocated what the file claimed; now each is a FileError naming the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "core/common/error.h"
#include "core/io/little_endian.h"
#include "core/io/npz.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using io::put64;

struct CraftedEntry {
  std::string name = "a.npy";
  int method = 0;
  std::uint64_t compressedSize = 0, size = 0, localOffset = 0;
  bool zip64 = true;  // saturate the 32-bit fields and give the values in a zip64 extra
  int zip64ExtraLength = 24;
};

// A ZIP with one real stored entry (its local header and data at offset 0) and a central
// directory of the crafted entries, with a zip64 end record and locator when asked.
std::string craftedZip(const std::vector<CraftedEntry>& entries, std::uint64_t zip64EndOffset = 0,
                       bool useZip64End = false) {
  const std::string content = serializeNpy(NpyArray::from(std::vector<float>{1, 2, 3}));
  std::string out;
  io::put32(out, 0x04034b50);
  io::put16(out, 45);
  io::put16(out, 0);
  io::put16(out, 0);
  io::put16(out, 0);
  io::put16(out, 0);
  io::put32(out, 0);
  io::put32(out, static_cast<std::uint32_t>(content.size()));
  io::put32(out, static_cast<std::uint32_t>(content.size()));
  io::put16(out, 5);
  io::put16(out, 0);
  out += "a.npy" + content;

  const std::uint64_t directoryOffset = out.size();
  for (const auto& e : entries) {
    io::put32(out, 0x02014b50);
    io::put16(out, 45);
    io::put16(out, 45);
    io::put16(out, 0);
    io::put16(out, static_cast<std::uint32_t>(e.method));
    io::put16(out, 0);
    io::put16(out, 0);
    io::put32(out, 0);  // crc
    io::put32(out, e.zip64 ? 0xFFFFFFFFu : static_cast<std::uint32_t>(e.compressedSize));
    io::put32(out, e.zip64 ? 0xFFFFFFFFu : static_cast<std::uint32_t>(e.size));
    io::put16(out, static_cast<std::uint32_t>(e.name.size()));
    io::put16(out, e.zip64 ? 4 + static_cast<std::uint32_t>(e.zip64ExtraLength) : 0);
    io::put16(out, 0);
    io::put16(out, 0);
    io::put16(out, 0);
    io::put32(out, 0);
    io::put32(out, e.zip64 ? 0xFFFFFFFFu : static_cast<std::uint32_t>(e.localOffset));
    out += e.name;
    if (e.zip64) {
      io::put16(out, 0x0001);
      io::put16(out, static_cast<std::uint32_t>(e.zip64ExtraLength));
      std::string values;
      put64(values, e.size);
      put64(values, e.compressedSize);
      put64(values, e.localOffset);
      out += values.substr(0, static_cast<std::size_t>(e.zip64ExtraLength));
    }
  }
  const std::uint64_t directorySize = out.size() - directoryOffset;
  if (useZip64End) {
    const std::uint64_t recordOffset = out.size();
    io::put32(out, 0x06064b50);
    put64(out, 44);
    io::put16(out, 45);
    io::put16(out, 45);
    io::put32(out, 0);
    io::put32(out, 0);
    put64(out, entries.size());
    put64(out, entries.size());
    put64(out, directorySize);
    put64(out, directoryOffset);
    io::put32(out, 0x07064b50);  // locator
    io::put32(out, 0);
    put64(out, zip64EndOffset ? zip64EndOffset : recordOffset);
    io::put32(out, 1);
  }
  io::put32(out, 0x06054b50);
  io::put16(out, 0);
  io::put16(out, 0);
  io::put16(out, useZip64End ? 0xFFFF : static_cast<std::uint32_t>(entries.size()));
  io::put16(out, useZip64End ? 0xFFFF : static_cast<std::uint32_t>(entries.size()));
  io::put32(out, static_cast<std::uint32_t>(directorySize));
  io::put32(out, useZip64End ? 0xFFFFFFFFu : static_cast<std::uint32_t>(directoryOffset));
  io::put16(out, 0);
  return out;
}

// readNpz's error for the archive, which must name the file.
std::string npzError(const std::string& name, const std::string& bytes) {
  const fs::path path = test::freshTempDir() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  try {
    readNpz(path);
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path.string(), 0), 0u) << e.what();
    return e.what();
  }
  return "no error";
}

TEST(Zip64Bounds, LocalOffsetThatWrapsAroundIsRefused) {
  // The valgrind finding: two zip64 entries whose local header would lie 13 and 16 bytes
  // before the start of the file once the offset wraps.
  CraftedEntry a, b;
  a.localOffset = ~std::uint64_t{0} - 12;  // 2^64 - 13
  b.localOffset = ~std::uint64_t{0} - 15;  // 2^64 - 16
  b.name = "b.npy";
  EXPECT_THAT(npzError("wrapped_offset.npz", craftedZip({a, b})), HasSubstr("bad local header"));
}

TEST(Zip64Bounds, DataRangeThatWrapsAroundIsRefused) {
  CraftedEntry e;
  e.compressedSize = ~std::uint64_t{0} - 40;
  e.size = e.compressedSize;
  EXPECT_THAT(npzError("wrapped_size.npz", craftedZip({e})), HasSubstr("truncated"));
}

TEST(Zip64Bounds, Zip64ExtraShorterThanItsFieldsIsRefused) {
  // The saturated fields need 24 bytes; the extra field declares (and holds) 4.
  CraftedEntry e;
  e.zip64ExtraLength = 4;
  EXPECT_THAT(npzError("short_extra.npz", craftedZip({e})), HasSubstr("zip64 extra field"));
}

TEST(Zip64Bounds, Zip64EndRecordOutsideTheFileIsRefused) {
  CraftedEntry e;
  e.size = e.compressedSize = 130;
  for (const std::uint64_t offset : {~std::uint64_t{0} - 19, std::uint64_t{1} << 40}) {
    EXPECT_THAT(npzError("zip64_end.npz", craftedZip({e}, offset, true)),
                HasSubstr("zip64 directory is corrupt"));
  }
}

TEST(Zip64Bounds, DirectoryOffsetOutsideTheFileIsRefused) {
  std::string bytes = craftedZip({CraftedEntry{}}, 0, true);
  // The zip64 end record's directory offset (its last 8 bytes, before the 20-byte locator and
  // the 22-byte end record) points far past the file, and to 2^64 - 10 (wraps).
  for (const std::uint64_t offset : {std::uint64_t{1} << 40, ~std::uint64_t{0} - 9}) {
    std::string crafted = bytes;
    std::string value;
    put64(value, offset);
    crafted.replace(crafted.size() - 22 - 20 - 8, 8, value);
    EXPECT_THAT(npzError("directory_offset.npz", crafted), HasSubstr("central directory"));
  }
}

TEST(Zip64Bounds, ClaimedSizesAreCheckedBeforeAllocating) {
  // 1 TB uncompressed from a few bytes of deflate data: refused before any allocation
  // (deflate cannot expand more than 1032:1), not a bad_alloc.
  CraftedEntry deflated;
  deflated.method = 8;
  deflated.compressedSize = 130;
  deflated.size = std::uint64_t{1} << 40;
  EXPECT_THAT(npzError("terabyte.npz", craftedZip({deflated})), HasSubstr("claims"));
  // A stored entry's two sizes must agree.
  CraftedEntry stored;
  stored.compressedSize = 130;
  stored.size = std::uint64_t{4} << 30;
  EXPECT_THAT(npzError("stored_sizes.npz", craftedZip({stored})), HasSubstr("claims"));
}

}  // namespace
}  // namespace sagrid
