#include "core/io/zip_archive.h"

#include <zlib.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/io/little_endian.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

using io::u16;
using io::u32;
using io::u64;
using io::put16;
using io::put32;

// Every offset and size below comes from the file: a range is checked as `at <= size && length <=
// size - at`, never as `at + length > size`, which wraps around for offsets near 2^64 (a crafted
// zip64 offset of 2^64 - 13 made that check pass and the read land 13 bytes before the buffer).
bool inside(std::uint64_t at, std::uint64_t length, std::size_t size) {
  return at <= size && length <= size - at;
}

// Deflate cannot expand data more than 1032:1, so a larger claimed size is a lie, refused before
// anything is allocated for it.
constexpr std::uint64_t kMaxDeflateRatio = 1032;
// zlib's counters and our CRC check take 32-bit lengths.
constexpr std::uint64_t kMaxEntrySize = 0xFFFFFFFFu;

std::string inflateRaw(std::string_view compressed, std::size_t size, const fs::path& source,
                       const std::string& entry) {
  std::string out(size, '\0');
  z_stream stream{};
  if (inflateInit2(&stream, -MAX_WBITS) != Z_OK)
    throw FileError(source, "zlib initialisation failed");
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  stream.avail_in = static_cast<uInt>(compressed.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int status = inflate(&stream, Z_FINISH);
  const std::size_t produced = stream.total_out;
  inflateEnd(&stream);
  if (status != Z_STREAM_END || produced != size) {
    throw FileError(source, "entry '" + entry + "' is corrupt (deflate data does not decompress)");
  }
  return out;
}

}  // namespace

ZipArchive ZipArchive::open(const fs::path& path) { return fromBytes(readFileBytes(path), path); }

ZipArchive ZipArchive::fromBytes(std::string bytes, const fs::path& source) {
  ZipArchive archive;
  archive.m_path = source;
  archive.m_bytes = std::move(bytes);
  const std::string_view b(archive.m_bytes);
  const fs::path& path = archive.m_path;
  // End of central directory: 22 bytes plus a comment of at most 64 KiB at the end of the file.
  if (b.size() < 22) throw FileError(path, "is not a zip archive: too short");
  std::size_t eocd = std::string_view::npos;
  const std::size_t lowest = b.size() > 22 + 65535 ? b.size() - 22 - 65535 : 0;
  for (std::size_t at = b.size() - 22 + 1; at-- > lowest;) {
    if (u32(b, at) == 0x06054b50) {
      eocd = at;
      break;
    }
  }
  if (eocd == std::string_view::npos) throw FileError(path, "is not a zip archive or is truncated");
  std::uint64_t entries = u16(b, eocd + 10);
  std::uint64_t directoryOffset = u32(b, eocd + 16);
  if ((directoryOffset == 0xFFFFFFFFu || entries == 0xFFFF) && eocd >= 20 &&
      u32(b, eocd - 20) == 0x07064b50) {
    const std::uint64_t zip64End = u64(b, eocd - 20 + 8);  // zip64 end of central directory
    if (!inside(zip64End, 56, b.size()) || u32(b, zip64End) != 0x06064b50) {
      throw FileError(path, "zip64 directory is corrupt");
    }
    entries = u64(b, zip64End + 32);
    directoryOffset = u64(b, zip64End + 48);
  }

  std::size_t at = directoryOffset;
  for (std::uint64_t e = 0; e < entries; ++e) {
    if (!inside(at, 46, b.size()) || u32(b, at) != 0x02014b50)
      throw FileError(path, "zip central directory is corrupt");
    ZipEntry entry;
    entry.method = u16(b, at + 10);
    entry.crc = u32(b, at + 16);
    entry.compressedSize = u32(b, at + 20);
    entry.size = u32(b, at + 24);
    const std::size_t nameLength = u16(b, at + 28), extraLength = u16(b, at + 30),
                      commentLength = u16(b, at + 32);
    entry.localOffset = u32(b, at + 42);
    if (!inside(at + 46, nameLength + extraLength, b.size()))
      throw FileError(path, "zip central directory is truncated");
    entry.name = std::string(b.substr(at + 46, nameLength));
    // Zip64 extra field: the 64-bit values of whichever fields were saturated, in this order.
    const std::size_t extraEnd = at + 46 + nameLength + extraLength;
    for (std::size_t x = at + 46 + nameLength; x + 4 <= extraEnd;) {
      const std::size_t id = u16(b, x), length = u16(b, x + 2);
      const std::size_t end = x + 4 + length;
      if (end > extraEnd)
        throw FileError(path, "entry '" + entry.name + "': an extra field overruns its header");
      if (id == 0x0001) {
        std::size_t field = x + 4;
        auto next = [&]() {
          if (field + 8 > end) {
            throw FileError(path, "entry '" + entry.name +
                                      "': zip64 extra field is shorter than the sizes it replaces");
          }
          field += 8;
          return u64(b, field - 8);
        };
        if (entry.size == 0xFFFFFFFFu) entry.size = next();
        if (entry.compressedSize == 0xFFFFFFFFu) entry.compressedSize = next();
        if (entry.localOffset == 0xFFFFFFFFu) entry.localOffset = next();
      }
      x = end;
    }
    at += 46 + nameLength + extraLength + commentLength;
    archive.m_entries.push_back(std::move(entry));
  }
  return archive;
}

const ZipEntry* ZipArchive::find(const std::string& name) const {
  for (const auto& e : m_entries) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::string ZipArchive::read(const std::string& name) const {
  const ZipEntry* entry = find(name);
  if (!entry) throw FileError(m_path, "has no entry '" + name + "'");
  return read(*entry);
}

std::string ZipArchive::read(const ZipEntry& entry) const {
  const std::string_view b(m_bytes);
  const std::string& name = entry.name;
  if (!inside(entry.localOffset, 30, b.size()) || u32(b, entry.localOffset) != 0x04034b50) {
    throw FileError(m_path, "entry '" + name + "' is corrupt (bad local header)");
  }
  const std::size_t dataStart =
      entry.localOffset + 30 + u16(b, entry.localOffset + 26) + u16(b, entry.localOffset + 28);
  if (!inside(dataStart, entry.compressedSize, b.size()))
    throw FileError(m_path, "entry '" + name + "' is truncated");
  const bool sizeIsPossible = entry.method == 0
                                  ? entry.size == entry.compressedSize
                                  : entry.size <= kMaxDeflateRatio * entry.compressedSize + 64;
  if (!sizeIsPossible || entry.size > kMaxEntrySize) {
    throw FileError(m_path, "entry '" + name + "' claims " + std::to_string(entry.size) +
                                " bytes uncompressed from " + std::to_string(entry.compressedSize) +
                                (entry.size > kMaxEntrySize && sizeIsPossible
                                     ? " (entries over 4 GiB are not supported)"
                                     : " stored (impossible: the archive is corrupt or crafted)"));
  }
  const std::string_view stored = b.substr(dataStart, entry.compressedSize);
  std::string content;
  if (entry.method == 0) {
    content = std::string(stored);
  } else if (entry.method == 8) {
    content = inflateRaw(stored, entry.size, m_path, name);
  } else {
    throw FileError(m_path, "entry '" + name + "' uses zip compression method " +
                                std::to_string(entry.method) +
                                " (only stored and deflate are supported)");
  }
  if (crc32(0L, reinterpret_cast<const Bytef*>(content.data()),
            static_cast<uInt>(content.size())) != entry.crc) {
    throw FileError(m_path, "entry '" + name + "' is corrupt (CRC mismatch)");
  }
  return content;
}

std::string serializeStoredZip(const std::vector<std::pair<std::string, std::string>>& entries,
                               const fs::path& target) {
  std::string out, directory;
  std::uint32_t count = 0;
  for (const auto& entry : entries) {
    // Named references, not a structured binding: C++17 lambdas cannot capture bindings (clang).
    const std::string& name = entry.first;
    const std::string& content = entry.second;
    if (content.size() >= 0xFFFFFFFFu || out.size() >= 0xFFFFFFFFu) {
      throw FileError(target, "entry '" + name + "' is too large for a non-zip64 archive");
    }
    if (count == 0xFFFF) throw FileError(target, "too many entries for a non-zip64 archive");
    const std::uint32_t crc = static_cast<std::uint32_t>(crc32(
        0L, reinterpret_cast<const Bytef*>(content.data()), static_cast<uInt>(content.size())));
    const auto offset = static_cast<std::uint32_t>(out.size());
    auto common = [&](std::string& h) {
      put16(h, 20);    // version needed: 2.0
      put16(h, 0);     // flags
      put16(h, 0);     // method: stored
      put16(h, 0);     // time
      put16(h, 0x21);  // date: 1980-01-01
      put32(h, crc);
      put32(h, static_cast<std::uint32_t>(content.size()));
      put32(h, static_cast<std::uint32_t>(content.size()));
      put16(h, static_cast<std::uint32_t>(name.size()));
      put16(h, 0);  // extra length
    };
    put32(out, 0x04034b50);
    common(out);
    out += name;
    out += content;

    put32(directory, 0x02014b50);
    put16(directory, 20);  // version made by
    common(directory);
    put16(directory, 0);  // comment length
    put16(directory, 0);  // disk number
    put16(directory, 0);  // internal attributes
    put32(directory, 0);  // external attributes
    put32(directory, offset);
    directory += name;
    ++count;
  }
  const auto directoryOffset = static_cast<std::uint32_t>(out.size());
  out += directory;
  put32(out, 0x06054b50);
  put16(out, 0);
  put16(out, 0);
  put16(out, count);
  put16(out, count);
  put32(out, static_cast<std::uint32_t>(directory.size()));
  put32(out, directoryOffset);
  put16(out, 0);
  return out;
}

void writeStoredZip(const fs::path& path,
                    const std::vector<std::pair<std::string, std::string>>& entries) {
  writeFileAtomic(path, serializeStoredZip(entries, path));
}

}  // namespace sagrid
