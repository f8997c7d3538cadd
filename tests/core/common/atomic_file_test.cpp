#include "core/common/atomic_file.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "support/test_paths.h"

namespace sagrid {
namespace fs = std::filesystem;

TEST(AtomicFile, WritesAndReplaces) {
  const fs::path dir = test::freshTempDir();
  const fs::path target = dir / "out.txt";
  writeFileAtomic(target, "first");
  writeFileAtomic(target, "second");
  EXPECT_EQ(readFileBytes(target), "second");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, UncommittedWriteLeavesTargetUntouched) {
  const fs::path dir = test::freshTempDir();
  const fs::path target = dir / "out.txt";
  writeFileAtomic(target, "kept");
  {
    AtomicOutputFile out(target);
    out.stream() << "partial";
  }  // no commit: as if an exception had been thrown
  EXPECT_EQ(readFileBytes(target), "kept");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, MissingFolderIsAFileError) {
  const fs::path target = test::freshTempDir() / "no" / "such" / "out.txt";
  EXPECT_THROW(writeFileAtomic(target, "x"), FileError);
}

TEST(AtomicFile, ReadErrorsNameTheFile) {
  const fs::path dir = test::freshTempDir();
  try {
    readFileBytes(dir / "missing.json");
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.json"), std::string::npos);
  }
  EXPECT_THROW(readFileBytes(dir), FileError);
}

// Until commit() nothing but the old target is visible in the folder (the temporary is unnamed),
// and after it only the target: a kill -9 at any moment leaves no temporary behind.
TEST(AtomicFile, NothingButTheTargetIsEverVisible) {
  const fs::path dir = test::freshTempDir();
  const fs::path target = dir / "out.txt";
  writeFileAtomic(target, "old");
  AtomicOutputFile out(target);
  out.stream() << std::string(1 << 20, 'x');
  out.stream().flush();
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  EXPECT_EQ(readFileBytes(target), "old");
  out.commit();
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  EXPECT_EQ(readFileBytes(target).size(), std::size_t{1} << 20);
}

TEST(AtomicFile, NewFilesGetTheUsualPermissions) {
  const fs::path target = test::freshTempDir() / "new.txt";
  writeFileAtomic(target, "x");
  struct stat info {};
  ASSERT_EQ(::stat(target.c_str(), &info), 0);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask);
}

// A process killed between naming its temporary and renaming it leaves "<target>.tmp-<pid>-<n>";
// the next overwrite of that target removes it, but never one of a process still running.
TEST(AtomicFile, OverwriteRemovesTemporariesOfDeadProcesses) {
  const fs::path dir = test::freshTempDir();
  const fs::path target = dir / "labels.json";
  writeFileAtomic(target, "old");
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);  // its pid now names no process
  const fs::path stale = dir / ("labels.json.tmp-" + std::to_string(child) + "-0");
  const fs::path live = dir / ("labels.json.tmp-" + std::to_string(::getpid()) + "-999");
  const fs::path other = dir / ("other.json.tmp-" + std::to_string(child) + "-0");
  for (const auto& p : {stale, live, other}) writeFileAtomic(p, "partial");
  writeFileAtomic(target, "new");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));  // another target's business
  EXPECT_EQ(readFileBytes(target), "new");
}

// The message readFileBytes gives for `path`; fails the test when it reads.
std::string readError(const fs::path& path, std::uint64_t maxBytes = kMaxInputFileBytes) {
  try {
    readFileBytes(path, maxBytes);
  } catch (const FileError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    return message;
  }
  ADD_FAILURE() << path << " was read";
  return "";
}

// Issue 14: a FIFO hung every command, /dev/zero ran out of memory after 10 s.
TEST(ReadFileBytes, OnlyRegularFiles) {
  const fs::path dir = test::freshTempDir();
  const fs::path fifo = dir / "labels.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THAT(readError(fifo), ::testing::HasSubstr("FIFO"));
  EXPECT_THAT(readError("/dev/zero"), ::testing::HasSubstr("is a device"));
  EXPECT_THAT(readError(dir), ::testing::HasSubstr("is a directory"));
  EXPECT_THROW(requireRegularFile(fifo), FileError);
  EXPECT_THROW(requireRegularFile("/dev/zero"), FileError);
}

TEST(ReadFileBytes, SymlinkLoopAndLongNamesAreNamed) {
  const fs::path dir = test::freshTempDir();
  fs::create_symlink(dir / "b.obj", dir / "a.obj");
  fs::create_symlink(dir / "a.obj", dir / "b.obj");
  EXPECT_THAT(readError(dir / "a.obj"), ::testing::HasSubstr("symbolic link loop"));
  EXPECT_THAT(readError(dir / (std::string(300, 'x') + ".obj")),
              ::testing::HasSubstr("file name too long"));
}

TEST(ReadFileBytes, RefusesFilesOverTheLimitBeforeReading) {
  const fs::path path = test::freshTempDir() / "big.bin";
  writeFileAtomic(path, std::string(4096, 'x'));
  EXPECT_THAT(readError(path, 1000), ::testing::HasSubstr("larger than the 1000 bytes"));
  EXPECT_EQ(readFileBytes(path, 4096).size(), 4096u);
}

}  // namespace sagrid
