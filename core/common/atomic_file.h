// Atomic file writes: content goes to a temporary file beside the target and is renamed over it
// only when complete, so a crash or an error never leaves a partial or truncated file.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace sagrid {

// Writes through a temporary sibling file; commit() renames it onto the target. If the object is
// destroyed without commit() (an exception, an early return), the temporary file is removed and
// the target is untouched.
class AtomicOutputFile {
 public:
  explicit AtomicOutputFile(std::filesystem::path target, bool binary = true);
  ~AtomicOutputFile();
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  std::ostream& stream() { return m_stream; }
  const std::filesystem::path& target() const { return m_target; }
  void commit();  // throws FileError when the write or the rename fails

 private:
  std::filesystem::path m_target;
  std::filesystem::path m_temp;
  std::ofstream m_stream;
  bool m_committed = false;
};

void writeFileAtomic(const std::filesystem::path& target, std::string_view bytes);

// Reads a whole file; throws FileError for missing files, directories and read errors.
std::string readFileBytes(const std::filesystem::path& path);

}  // namespace sagrid
