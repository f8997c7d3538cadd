#include "core/annotate/run_manifest.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <set>

#include "core/common/error.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

TEST(RunManifest, ConcurrentAppendsFromManyProcessesStayWholeLines) {
  const auto file = test::freshTempDir() / "annotate.jsonl";
  constexpr int kProcesses = 4, kLines = 150;
  const std::string padding(3000, 'x');  // longer than one small write
  std::vector<pid_t> pids;
  for (int p = 0; p < kProcesses; ++p) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      for (int i = 0; i < kLines; ++i)
        appendManifestLine(
            file, {{"object", std::to_string(p) + "-" + std::to_string(i)}, {"padding", padding}});
      ::_exit(0);
    }
    pids.push_back(pid);
  }
  for (const pid_t pid : pids) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_EQ(WEXITSTATUS(status), 0);
  }
  // Every raw line is one complete JSON object (readManifest would hide torn ones).
  std::ifstream in(file);
  std::string raw;
  std::set<std::string> objects;
  while (std::getline(in, raw)) {
    const auto j = nlohmann::json::parse(raw);
    objects.insert(j.at("object").get<std::string>());
    EXPECT_EQ(j.at("padding"), padding);
  }
  EXPECT_EQ(objects.size(), static_cast<std::size_t>(kProcesses * kLines));
  EXPECT_EQ(readManifest(file).size(), static_cast<std::size_t>(kProcesses * kLines));
}

TEST(RunManifest, LatestLineOfEachObjectWinsAndTornLinesAreSkipped) {
  const auto file = test::freshTempDir() / "annotate.jsonl";
  appendManifestLine(file, {{"object", "a"}, {"status", "failed"}});
  appendManifestLine(file, {{"object", "b"}, {"status", "annotated"}});
  { std::ofstream(file, std::ios::app) << "{\"object\": \"a\", \"sta"; }
  { std::ofstream(file, std::ios::app) << "\n"; }
  appendManifestLine(file, {{"object", "a"}, {"status", "annotated"}});
  const auto latest = latestByObject(readManifest(file));
  ASSERT_EQ(latest.size(), 2u);
  EXPECT_EQ(latest.at("a").at("status"), "annotated");
  EXPECT_EQ(latest.at("b").at("status"), "annotated");
}

TEST(RunManifest, AnUnwritableManifestIsAClearError) {
  const auto dir = test::freshTempDir();
  std::ofstream(dir / "file") << "x";
  EXPECT_THROW(appendManifestLine(dir / "file" / "annotate.jsonl", {{"object", "a"}}), FileError);
}

}  // namespace
}  // namespace sagrid
