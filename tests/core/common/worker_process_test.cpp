#include "core/common/worker_process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/die_by_signal.h"
#include <unistd.h>

#include <csignal>
#include <stdexcept>

namespace sagrid {
namespace {
using ::testing::HasSubstr;
using Read = WorkerProcess::Read;

TEST(WorkerProcess, ReportsLinesThenEndsCleanly) {
  WorkerProcess w([](const WorkerProcess::Report& report) {
    report("one");
    report("two {\"x\": 1}");
  });
  std::string line;
  ASSERT_EQ(w.readLine(line, 10), Read::Line);
  EXPECT_EQ(line, "one");
  ASSERT_EQ(w.readLine(line, 10), Read::Line);
  EXPECT_EQ(line, "two {\"x\": 1}");
  EXPECT_EQ(w.readLine(line, 10), Read::Ended);
  EXPECT_TRUE(w.ended());
  EXPECT_TRUE(w.endedCleanly());
  EXPECT_EQ(w.endDescription(), "exited with status 0");
  EXPECT_GT(w.peakRssKiB(), 0);
}

TEST(WorkerProcess, TimesOutOnAHungChildAndKillsIt) {
  WorkerProcess w([](const WorkerProcess::Report& report) {
    report("started");
    for (;;) ::pause();
  });
  std::string line;
  ASSERT_EQ(w.readLine(line, 10), Read::Line);
  EXPECT_EQ(w.readLine(line, 0.2), Read::Timeout);
  EXPECT_FALSE(w.ended());
  w.kill();
  EXPECT_TRUE(w.ended());
  EXPECT_THAT(w.endDescription(), HasSubstr("killed by signal 9"));
}

TEST(WorkerProcess, DescribesACrashAndAnEscapedException) {
  WorkerProcess crash([](const WorkerProcess::Report&) { test::dieBySignal(SIGSEGV); });
  std::string line;
  EXPECT_EQ(crash.readLine(line, 10), Read::Ended);
  EXPECT_THAT(crash.endDescription(), HasSubstr("killed by signal 11"));
  EXPECT_FALSE(crash.endedCleanly());

  WorkerProcess thrower([](const WorkerProcess::Report&) { throw std::runtime_error("boom"); });
  EXPECT_EQ(thrower.readLine(line, 10), Read::Ended);
  EXPECT_EQ(thrower.endDescription(), "exited with status 1");
}

TEST(WorkerProcess, DestructorStopsAChildStillRunning) {
  pid_t child = 0;
  {
    WorkerProcess w([&](const WorkerProcess::Report& report) {
      report(std::to_string(::getpid()));
      for (;;) ::pause();
    });
    std::string line;
    ASSERT_EQ(w.readLine(line, 10), Read::Line);
    child = std::stoi(line);
  }
  EXPECT_NE(::kill(child, 0), 0);  // reaped: no such process
}

}  // namespace
}  // namespace sagrid
