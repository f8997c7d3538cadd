// ZIP archives: the one reader and writer behind .npz files and the Sweet Home 3D corpus (.sh3f
// furniture libraries and the application .jar are ZIPs). Reads stored and deflate entries,
// zip64 directories, and checks every entry's CRC; writes stored entries only (no zip64).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sagrid {

struct ZipEntry {
  std::string name;  // as stored: '/'-separated, no leading '/'
  int method = 0;    // 0 stored, 8 deflate
  std::uint32_t crc = 0;
  std::uint64_t compressedSize = 0;
  std::uint64_t size = 0;
  std::uint64_t localOffset = 0;
  bool isDirectory() const { return !name.empty() && name.back() == '/'; }
};

// The whole archive is held in memory (our archives are at most tens of MiB). Every error is a
// FileError naming the archive and, where there is one, the entry.
class ZipArchive {
 public:
  static ZipArchive open(const std::filesystem::path& path);
  // `source` names the archive in error messages.
  static ZipArchive fromBytes(std::string bytes, const std::filesystem::path& source);

  const std::filesystem::path& path() const { return m_path; }
  const std::vector<ZipEntry>& entries() const { return m_entries; }
  const ZipEntry* find(const std::string& name) const;  // nullptr when absent
  bool contains(const std::string& name) const { return find(name) != nullptr; }

  // The uncompressed bytes of an entry; throws FileError when it is absent or corrupt.
  std::string read(const std::string& name) const;
  std::string read(const ZipEntry& entry) const;

 private:
  std::filesystem::path m_path;
  std::string m_bytes;
  std::vector<ZipEntry> m_entries;
};

// A ZIP of stored entries, in the given order; `target` names the file in error messages.
std::string serializeStoredZip(const std::vector<std::pair<std::string, std::string>>& entries,
                               const std::filesystem::path& target);
void writeStoredZip(const std::filesystem::path& path,
                    const std::vector<std::pair<std::string, std::string>>& entries);  // atomic

}  // namespace sagrid
