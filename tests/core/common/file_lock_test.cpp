#include "core/common/file_lock.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "support/test_paths.h"

namespace sagrid {
namespace {

TEST(FileLock, ExcludesASecondHolderUntilReleased) {
  const auto file = test::freshTempDir() / "locks" / "obj.lock";
  auto first = FileLock::tryAcquire(file);
  ASSERT_TRUE(first.has_value());
  EXPECT_FALSE(FileLock::tryAcquire(file).has_value());  // flock is per open file: excluded
  // Another process sees it held too.
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(FileLock::tryAcquire(file).has_value() ? 1 : 0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  first.reset();
  EXPECT_TRUE(FileLock::tryAcquire(file).has_value());
}

TEST(FileLock, IsReleasedWhenItsHolderIsKilled) {
  const auto file = test::freshTempDir() / "obj.lock";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    auto lock = FileLock::tryAcquire(file);
    (void)!::write(ready[1], lock ? "y" : "n", 1);
    for (;;) ::pause();
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  EXPECT_EQ(c, 'y');
  EXPECT_FALSE(FileLock::tryAcquire(file).has_value());
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  EXPECT_TRUE(FileLock::tryAcquire(file).has_value());
  ::close(ready[0]);
  ::close(ready[1]);
}

}  // namespace
}  // namespace sagrid
