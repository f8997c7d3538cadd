#include "core/common/atomic_file.h"

#include <atomic>
#include <system_error>
#include <unistd.h>

#include "core/common/error.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {
fs::path temporarySibling(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  fs::path temp = target;
  temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return temp;
}
}  // namespace

AtomicOutputFile::AtomicOutputFile(fs::path target, bool binary)
    : m_target(std::move(target)), m_temp(temporarySibling(m_target)) {
  if (m_target.has_parent_path() && !fs::is_directory(m_target.parent_path())) {
    throw FileError(m_target, "the folder " + m_target.parent_path().string() + " does not exist");
  }
  m_stream.open(m_temp, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
  if (!m_stream) throw FileError(m_target, "cannot be written (permission denied or disk full?)");
}

AtomicOutputFile::~AtomicOutputFile() {
  if (!m_committed) {
    m_stream.close();
    std::error_code ignored;
    fs::remove(m_temp, ignored);  // best effort: the target was never touched
  }
}

void AtomicOutputFile::commit() {
  m_stream.flush();
  if (!m_stream) throw FileError(m_target, "write failed (disk full?)");
  m_stream.close();
  std::error_code ec;
  fs::rename(m_temp, m_target, ec);
  if (ec) throw FileError(m_target, "cannot replace the file: " + ec.message());
  m_committed = true;
}

void writeFileAtomic(const fs::path& target, std::string_view bytes) {
  AtomicOutputFile out(target);
  out.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.commit();
}

std::string readFileBytes(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw FileError(path, "file not found");
  if (fs::is_directory(path, ec)) throw FileError(path, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot be opened for reading (permission denied?)");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw FileError(path, "read error");
  return bytes;
}

}  // namespace sagrid
