// Issue 14, kill -9 safety: `annotate` and `export` are killed at random moments (20 times each);
// after every kill each file they left is absent or complete and valid, and a rerun completes,
// writes the same files as an uninterrupted run and leaves no temporary file. The moments are
// drawn from a fixed seed over the length of an uninterrupted run.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <random>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/output_check.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kKills = 20;

// Runs sagrid with `args`; with `killAfter` it is killed with SIGKILL that long after the start
// (if it is still running). Returns the exit code, or -1 when it was killed.
int runSagridProcess(const std::vector<std::string>& args,
                     std::optional<std::chrono::microseconds> killAfter = std::nullopt) {
  std::vector<std::string> argv{test::sagridBinary().string()};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> raw;
  for (auto& a : argv) raw.push_back(a.data());
  raw.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    if (!std::getenv("SAGRID_TEST_VERBOSE")) std::freopen("/dev/null", "w", stderr);
    ::execv(raw[0], raw.data());
    ::_exit(127);
  }
  if (killAfter) {
    std::this_thread::sleep_for(*killAfter);
    ::kill(pid, SIGKILL);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Copies two shipped sample objects (mesh, material) into DIR/in/<id>/.
fs::path sampleObjects(const fs::path& dir) {
  const fs::path samples = fs::path(SAGRID_SOURCE_DIR) / "resources" / "samples";
  int copied = 0;
  for (const auto& entry : fs::directory_iterator(samples)) {
    if (!entry.is_directory() || copied == 2) continue;
    fs::create_directories(dir / "in" / entry.path().filename());
    for (const auto& file : fs::directory_iterator(entry.path()))
      fs::copy_file(file.path(), dir / "in" / entry.path().filename() / file.path().filename());
    ++copied;
  }
  return dir / "in";
}

// Kills `args` (which write to `out`) kKills times at moments spread over one clean run, checks
// the files after each kill, then reruns and compares with the clean run's files.
void killAtRandomMoments(const fs::path& dir, const std::function<std::vector<std::string>(const fs::path&)>& args) {
  const fs::path reference = dir / "reference";
  const auto start = Clock::now();
  ASSERT_EQ(runSagridProcess(args(reference)), 0);
  const auto clean = std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
  ASSERT_TRUE(test::invalidOutputs(reference).empty());

  const fs::path out = dir / "out";
  std::mt19937 random(14);
  std::uniform_int_distribution<long> moment(0, clean.count());
  int killedMidway = 0;
  for (int k = 0; k < kKills; ++k) {
    killedMidway += runSagridProcess(args(out), std::chrono::microseconds(moment(random))) == -1;
    if (!fs::exists(out)) continue;
    EXPECT_THAT(test::invalidOutputs(out), ::testing::IsEmpty()) << "after kill " << k;
  }
  EXPECT_GE(killedMidway, kKills / 2) << "most kills must land while the command runs";
  ASSERT_EQ(runSagridProcess(args(out)), 0);
  EXPECT_THAT(test::invalidOutputs(out), ::testing::IsEmpty());
  EXPECT_THAT(test::temporaryFiles(out), ::testing::IsEmpty());
  EXPECT_EQ(test::relativeFiles(out), test::relativeFiles(reference));
}

TEST(KillSafetySlow, AnnotateKilledAtRandomMoments) {
  const fs::path dir = test::freshTempDir();
  const fs::path in = sampleObjects(dir);
  const std::string models = (fs::path(SAGRID_SOURCE_DIR) / "resources" / "models").string();
  // --force: every run annotates again, so every kill lands in real work.
  killAtRandomMoments(dir, [&](const fs::path& out) {
    return std::vector<std::string>{"annotate", in.string(), "--out", out.string(), "--models",
                                    models, "--symmetries", "1", "--force"};
  });
}

TEST(KillSafetySlow, ExportKilledAtRandomMoments) {
  const fs::path dir = test::freshTempDir();
  const fs::path in = sampleObjects(dir);
  const std::string models = (fs::path(SAGRID_SOURCE_DIR) / "resources" / "models").string();
  // labels.json beside each mesh: a folder of objects, what export reads.
  ASSERT_EQ(runSagridProcess({"annotate", in.string(), "--out", in.string(), "--models", models,
                              "--symmetries", "1"}),
            0);
  killAtRandomMoments(dir, [&](const fs::path& out) {
    return std::vector<std::string>{"export", in.string(), "--format", "mjcf",
                                    "--out", out.string(), "--collision", "hull"};
  });
}

}  // namespace
}  // namespace sagrid
