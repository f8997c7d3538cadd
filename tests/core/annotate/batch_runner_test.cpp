#include "core/annotate/batch_runner.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

#include "core/annotate/run_manifest.h"
#include "core/common/error.h"
#include "support/die_by_signal.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::vector<MeshFile> objects(const std::vector<std::string>& ids) {
  std::vector<MeshFile> files;
  for (const auto& id : ids) files.push_back({id + ".obj", id});
  return files;
}

// A task that behaves by object id: "hang" never returns, "crash" segfaults, "throw" throws,
// anything else is annotated with its worker's pid (to count worker restarts).
ObjectTask scriptedTask() {
  return [](const MeshFile& f) -> nlohmann::json {
    if (f.id == "hang")
      for (;;) ::pause();
    if (f.id == "crash") test::dieBySignal(SIGSEGV);
    if (f.id == "throw") throw Error("broken mesh");
    return {{"status", batch_status::kAnnotated}, {"points", 2}, {"pid", ::getpid()}};
  };
}

TEST(BatchRunner, AHangingCrashingOrThrowingObjectFailsAloneAndTheBatchGoesOn) {
  const fs::path out = test::freshTempDir();
  BatchOptions options;
  options.out = out;
  options.timeLimitSeconds = 1;
  options.shard = {1, 3};
  int setups = 0;
  const auto files = objects({"a", "hang", "b", "crash", "c", "throw", "d"});
  const BatchSummary s = runBatch(files, options, [&setups] {
    ++setups;  // counted in the parent's copy only when run there: it is not
    return scriptedTask();
  });
  EXPECT_EQ(setups, 0);  // setup runs in the worker processes, never in the caller
  EXPECT_EQ(s.objects, 7u);
  EXPECT_EQ(s.count(batch_status::kAnnotated), 4u);
  EXPECT_EQ(s.count(batch_status::kFailed), 3u);
  EXPECT_EQ(s.points, 8u);
  EXPECT_EQ(s.workerRestarts, 2u);  // after the hang and after the crash

  const auto lines = readManifest(out / kRunManifestFile);
  ASSERT_EQ(lines.size(), 7u);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i].at("object"), files[i].id);  // in order, one line each
    EXPECT_EQ(lines[i].at("shard"), "1/3");
    EXPECT_TRUE(lines[i].contains("host"));
  }
  EXPECT_THAT(lines[1].at("error").get<std::string>(), HasSubstr("time limit of 1 s"));
  EXPECT_THAT(lines[3].at("error").get<std::string>(), HasSubstr("killed by signal 11"));
  EXPECT_EQ(lines[5].at("error"), "broken mesh");
  // a and b ran in different workers (the hung one was replaced), c and d in a third.
  EXPECT_NE(lines[0].at("pid"), lines[2].at("pid"));
  EXPECT_NE(lines[2].at("pid"), lines[4].at("pid"));
  EXPECT_EQ(lines[4].at("pid"), lines[6].at("pid"));
}

TEST(BatchRunner, AWorkerIsReplacedAfterItsQuotaOfObjects) {
  BatchOptions options;
  options.out = test::freshTempDir();
  options.objectsPerWorker = 2;
  const BatchSummary s = runBatch(objects({"a", "b", "c", "d", "e"}), options, scriptedTask);
  EXPECT_EQ(s.count(batch_status::kAnnotated), 5u);
  EXPECT_EQ(s.workerRestarts, 0u);  // retiring is not a failure
  const auto lines = readManifest(options.out / kRunManifestFile);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0].at("pid"), lines[1].at("pid"));
  EXPECT_NE(lines[1].at("pid"), lines[2].at("pid"));
  EXPECT_EQ(lines[2].at("pid"), lines[3].at("pid"));
  EXPECT_NE(lines[3].at("pid"), lines[4].at("pid"));
}

TEST(BatchRunner, ASetupFailureStopsTheBatchWithItsMessage) {
  BatchOptions options;
  options.out = test::freshTempDir();
  try {
    runBatch(objects({"a"}), options, []() -> ObjectTask { throw Error("models: no cards"); });
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "models: no cards");
  }
}

TEST(BatchRunner, AnOutputThatCannotBeWrittenStopsTheBatch) {
  BatchOptions options;
  options.out = test::freshTempDir();
  const auto files = objects({"a", "b", "c"});
  EXPECT_THROW(runBatch(files, options,
                        [] {
                          return [](const MeshFile&) -> nlohmann::json {
                            return {{"status", batch_status::kFailed},
                                    {"error", "No space left on device"},
                                    {"output_error", true}};
                          };
                        }),
               FileError);
  const auto lines = readManifest(options.out / kRunManifestFile);
  ASSERT_EQ(lines.size(), 1u);  // stopped after the first object
  EXPECT_FALSE(lines[0].contains("output_error"));
}

TEST(BatchRunner, AnOutputFolderThatCannotBeCreatedIsNamed) {
  const fs::path dir = test::freshTempDir();
  std::ofstream(dir / "file") << "x";
  try {
    requireWritableFolder(dir / "file" / "out");
    ADD_FAILURE() << "no error";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("file/out: cannot create the output folder"));
  }
}

// A run killed between writing its write probe and removing it leaves the probe; the next run
// takes it away with its own, so a rerun leaves the folder as an uninterrupted run does.
TEST(BatchRunner, AWriteProbeAKilledRunLeftIsRemovedByTheNext) {
  const fs::path out = test::freshTempDir() / "out";
  fs::create_directories(out);
  std::ofstream(out / ".sagrid-write-probe-999999") << "probe\n";
  std::ofstream(out / "labels-kept.json") << "{}";
  requireWritableFolder(out);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(out)) left.push_back(entry.path().filename().string());
  EXPECT_THAT(left, ::testing::ElementsAre("labels-kept.json"));
}

}  // namespace
}  // namespace sagrid
