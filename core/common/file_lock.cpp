#include "core/common/file_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/common/error.h"

namespace sagrid {
namespace {
int openLockFile(const std::filesystem::path& lockFile) {
  std::error_code ec;
  std::filesystem::create_directories(lockFile.parent_path(), ec);
  const int fd = ::open(lockFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw FileError(lockFile, std::string("cannot open lock file: ") + std::strerror(errno));
  return fd;
}

// flock, retried when a signal interrupts it; true when locked.
bool lockFd(int fd, int operation) {
  while (::flock(fd, operation) != 0) {
    if (errno != EINTR) return false;
  }
  return true;
}
}  // namespace

std::optional<FileLock> FileLock::tryAcquire(const std::filesystem::path& lockFile) {
  const int fd = openLockFile(lockFile);
  if (lockFd(fd, LOCK_EX | LOCK_NB)) return FileLock(fd);
  const int error = errno;
  ::close(fd);
  if (error == EWOULDBLOCK) return std::nullopt;
  throw FileError(lockFile, std::string("cannot lock: ") + std::strerror(error));
}

FileLock FileLock::acquire(const std::filesystem::path& lockFile) {
  const int fd = openLockFile(lockFile);
  if (lockFd(fd, LOCK_EX)) return FileLock(fd);
  const int error = errno;
  ::close(fd);
  throw FileError(lockFile, std::string("cannot lock: ") + std::strerror(error));
}

FileLock::FileLock(FileLock&& other) noexcept : m_fd(other.m_fd) { other.m_fd = -1; }

FileLock& FileLock::operator=(FileLock&& other) noexcept {
  if (this != &other) {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = other.m_fd;
    other.m_fd = -1;
  }
  return *this;
}

FileLock::~FileLock() {
  if (m_fd >= 0) ::close(m_fd);  // closing the descriptor releases the flock
}

}  // namespace sagrid
