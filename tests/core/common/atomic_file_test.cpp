#include "core/common/atomic_file.h"

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

}  // namespace sagrid
