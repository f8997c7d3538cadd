#include "core/common/atomic_file.h"

#include <ext/stdio_filebuf.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>

#include "core/common/error.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

using FdBuffer = __gnu_cxx::stdio_filebuf<char>;

fs::path temporarySibling(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  fs::path temp = target;
  temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return temp;
}

fs::path folderOf(const fs::path& target) {
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

// Removes "<target>.tmp-<pid>-<n>" siblings left by processes that no longer run (killed in the
// instant between naming a temporary and renaming it), so a rerun leaves no temporary behind.
// Only called before a named temporary is made, which is rare: first writes and O_TMPFILE
// writes of a new file need none.
void removeStaleTemporaries(const fs::path& target) {
  const std::string prefix = target.filename().string() + ".tmp-";
  std::error_code ec;
  for (fs::directory_iterator it(folderOf(target), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    const auto dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos ||
        rest.find_first_not_of("0123456789-") != std::string::npos)
      continue;
    const long pid = std::strtol(rest.substr(0, dash).c_str(), nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}


std::string errnoText(int error) { return std::generic_category().message(error); }

// Makes the folder's entry for a just-renamed file durable (a rename lives in the folder).
void syncFolder(const fs::path& folder, const fs::path& target) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // not every file system lets a folder be opened; the data is synced
  const int status = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  // EINVAL: the file system does not sync folders (some FUSE and network mounts).
  if (status != 0 && error != EINVAL) {
    throw FileError(target, "cannot make the write durable: " + errnoText(error));
  }
}

std::string byteCount(std::uint64_t bytes) {
  char text[32];
  if (bytes >= (std::uint64_t{1} << 30))
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1 << 30));
  else if (bytes >= (std::uint64_t{1} << 20))
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1 << 20));
  else
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  return text;
}

const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

[[noreturn]] void throwOpenError(const fs::path& path, int error) {
  switch (error) {
    case ENOENT: throw FileError(path, "file not found");
    case ELOOP: throw FileError(path, "cannot be opened: symbolic link loop");
    case ENAMETOOLONG: throw FileError(path, "cannot be opened: file name too long");
    case EACCES:
    case EPERM: throw FileError(path, "cannot be opened for reading (permission denied)");
    case ENOTDIR: throw FileError(path, "file not found (a folder on its path is a file)");
    default: throw FileError(path, "cannot be opened: " + errnoText(error));
  }
}

}  // namespace

AtomicOutputFile::AtomicOutputFile(fs::path target, bool binary) : m_target(std::move(target)) {
  const fs::path folder = folderOf(m_target);
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw FileError(m_target, "the folder " + folder.string() + " does not exist");
  }
  // An unnamed file: nothing is visible under any name until commit(), whenever we die. Naming
  // it later goes through /proc/self/fd.
  static const bool procMounted = ::access("/proc/self/fd", X_OK) == 0;
  if (procMounted) m_fd = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (m_fd < 0) {  // the file system has no O_TMPFILE: a named sibling
    removeStaleTemporaries(m_target);
    m_temp = temporarySibling(m_target);
    m_fd = ::open(m_temp.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0666);
  }
  if (m_fd < 0) {
    const int error = errno;
    m_temp.clear();
    throw FileError(m_target, "cannot be written: " + errnoText(error));
  }
  m_buffer = std::make_unique<FdBuffer>(m_fd, std::ios::out | (binary ? std::ios::binary
                                                                       : std::ios::openmode{}));
  m_stream.rdbuf(m_buffer.get());
}

AtomicOutputFile::~AtomicOutputFile() {
  m_stream.rdbuf(nullptr);
  m_buffer.reset();  // closes m_fd; an unnamed temporary vanishes with it
  if (!m_committed && !m_temp.empty()) {
    std::error_code ignored;
    fs::remove(m_temp, ignored);  // best effort: the target was never touched
  }
}

void AtomicOutputFile::publish() {
  if (!m_temp.empty()) return;  // already named
  const std::string self = "/proc/self/fd/" + std::to_string(m_fd);
  // A first write links straight to the target: no name but the final one ever exists.
  if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, m_target.c_str(), AT_SYMLINK_FOLLOW) == 0) {
    m_temp = m_target;
    return;
  }
  if (errno != EEXIST) throw FileError(m_target, "cannot be written: " + errnoText(errno));
  removeStaleTemporaries(m_target);
  m_temp = temporarySibling(m_target);
  if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, m_temp.c_str(), AT_SYMLINK_FOLLOW) != 0) {
    const int error = errno;
    m_temp.clear();
    throw FileError(m_target, "cannot be written: " + errnoText(error));
  }
}

void AtomicOutputFile::commit() {
  m_stream.flush();
  if (!m_stream) throw FileError(m_target, "write failed (disk full?)");
  if (::fsync(m_fd) != 0) {
    throw FileError(m_target, "write failed: " + errnoText(errno) + " (disk full?)");
  }
  publish();
  if (m_temp != m_target) {
    std::error_code ec;
    fs::rename(m_temp, m_target, ec);
    if (ec) throw FileError(m_target, "cannot replace the file: " + ec.message());
  }
  m_committed = true;
  syncFolder(folderOf(m_target), m_target);
}

void writeFileAtomic(const fs::path& target, std::string_view bytes) {
  AtomicOutputFile out(target);
  out.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.commit();
}

std::uint64_t requireRegularFile(const fs::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throwOpenError(path, errno);
  if (!S_ISREG(info.st_mode)) throw FileError(path, kindOf(info.st_mode));
  return static_cast<std::uint64_t>(info.st_size);
}

std::string readFileBytes(const fs::path& path, std::uint64_t maxBytes) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; fstat then refuses it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throwOpenError(path, errno);
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw FileError(path, "cannot be read: " + errnoText(errno));
  if (!S_ISREG(info.st_mode)) throw FileError(path, kindOf(info.st_mode));
  const auto size = static_cast<std::uint64_t>(info.st_size);
  if (size > maxBytes) {
    throw FileError(path, "is " + byteCount(size) + ", larger than the " + byteCount(maxBytes) +
                              " this file type may have");
  }
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileError(path, "read error: " + errnoText(errno));
    if (n == 0) break;  // shrank while we read
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace sagrid
