// Advisory, exclusive locks on lock files (flock), for work that two processes must not do at
// once, such as two array tasks annotating the same object into one output folder. The kernel
// releases a lock when its holder exits, however it exits (kill -9, a node's job killed), so a
// lock is never left stale; the lock file itself stays and is reused.
#pragma once

#include <filesystem>
#include <optional>

namespace sagrid {

class FileLock {
 public:
  // The lock on `lockFile` (created with its folder when missing), or nullopt when another
  // process holds it. Throws FileError when the file cannot be created or opened.
  static std::optional<FileLock> tryAcquire(const std::filesystem::path& lockFile);
  // Waits until the lock is free. Throws FileError as tryAcquire.
  static FileLock acquire(const std::filesystem::path& lockFile);

  FileLock(FileLock&& other) noexcept;
  FileLock& operator=(FileLock&& other) noexcept;
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  ~FileLock();  // releases

  int fd() const { return m_fd; }

 private:
  explicit FileLock(int fd) : m_fd(fd) {}
  int m_fd = -1;
};

}  // namespace sagrid
