// Atomic, durable file writes and bounded reads of user files.
// A write goes to an unnamed temporary file in the target's folder (O_TMPFILE; a named
// "<target>.tmp-<pid>-<n>" sibling where the file system lacks it), is fsynced, and only then
// gets the target's name (rename) with the folder fsynced too: after a crash, kill -9 or power
// loss the target is either the old file or the complete new one, and no temporary is left behind.
// Reads open only regular files (a FIFO, /dev/zero or a socket would hang or never end) and refuse
// files larger than a limit before allocating.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

namespace sagrid {

// Writes through a temporary file; commit() gives it the target's name. If the object is
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
  // Flushes, fsyncs, renames onto the target and fsyncs the folder; throws FileError when the
  // write, the sync or the rename fails.
  void commit();

 private:
  void publish();  // gives the synced temporary the target's name

  std::filesystem::path m_target;
  std::filesystem::path m_temp;  // empty while the temporary is unnamed (O_TMPFILE)
  int m_fd = -1;
  std::unique_ptr<std::streambuf> m_buffer;
  std::ostream m_stream{nullptr};
  bool m_committed = false;
};

void writeFileAtomic(const std::filesystem::path& target, std::string_view bytes);

// Largest file readFileBytes reads by default (meshes, archives); small formats pass less.
inline constexpr std::uint64_t kMaxInputFileBytes = std::uint64_t{2} << 30;  // 2 GiB
// Limit for small JSON documents a user or a dataset hands us (labels, model cards, manifests).
inline constexpr std::uint64_t kMaxJsonFileBytes = std::uint64_t{64} << 20;  // 64 MiB

// Throws FileError unless `path` names an existing regular file (after following symbolic
// links): missing, a symbolic link loop, a name too long, a directory, a FIFO, a device or a
// socket each get their own message. Returns the file's size.
std::uint64_t requireRegularFile(const std::filesystem::path& path);

// Reads a whole regular file; throws FileError (see requireRegularFile) and when it is larger
// than `maxBytes` or cannot be read.
std::string readFileBytes(const std::filesystem::path& path,
                          std::uint64_t maxBytes = kMaxInputFileBytes);

}  // namespace sagrid
