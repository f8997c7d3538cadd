// sagrid annotate as a batch from the command line (issue 13): shards that add up to one run,
// resume, curated labels kept, two tasks on one output, a read-only or full output, a mesh that
// never finishes importing, and filter's candidate list fed to annotate.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/annotate/run_manifest.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "support/same_labels.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::expectSameLabels;
using test::runCommand;
using test::runSagrid;
using test::shellQuote;
using ::testing::AnyOf;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kModels =
    shellQuote((fs::path(SAGRID_SOURCE_DIR) / "resources" / "models").string());
// One symmetric copy: these tests are about the batch, not the prediction.
const std::string kFast = " --models " + kModels + " --symmetries 1";

std::string q(const fs::path& p) { return test::quotedPath(p); }

std::string annotate(const fs::path& in, const fs::path& out, const std::string& more = "") {
  return "annotate " + q(in) + " --out " + q(out) + kFast + more;
}

// The status of each object in the manifest lines of one run (the last `n` lines).
std::map<std::string, std::string> lastStatuses(const fs::path& out) {
  std::map<std::string, std::string> statuses;
  for (const auto& [id, line] : latestByObject(readManifest(out / kRunManifestFile)))
    statuses[id] = line.at("status");
  return statuses;
}

TEST(AnnotateBatchCli, ShardSpecsOutsideTheArrayAreRejectedBeforeAnyWork) {
  const fs::path dir = test::freshTempDir();
  for (const char* spec : {"5/4", "0/0", "4/4", "x"}) {
    const auto r = runSagrid(annotate(dir / "in", dir / "out", std::string(" --shard ") + spec));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_THAT(r.output, HasSubstr(std::string("--shard ") + spec + ": expected I/N"));
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(AnnotateBatchCli, ShardsAddUpToOneRunAndARerunSkipsWhatIsDone) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 31}, {"sink", 2, 31}}, gen::MeshFormat::Mixed, dir / "in");
  auto r = runSagrid(annotate(dir / "in", dir / "one"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("annotated 4 of 4 objects"));
  std::size_t perShard[2];
  for (int i = 0; i < 2; ++i) {
    r = runSagrid(annotate(dir / "in", dir / "sharded", " --shard " + std::to_string(i) + "/2"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    perShard[i] = readManifest(dir / "sharded" / kRunManifestFile).size();
  }
  EXPECT_EQ(perShard[1], 4u);  // the two shards together: every object once
  EXPECT_GT(perShard[0], 0u);
  EXPECT_LT(perShard[0], 4u);
  for (const auto& [id, status] : lastStatuses(dir / "sharded")) {
    EXPECT_EQ(status, "annotated") << id;
    expectSameLabels(dir / "one" / id / "labels.json", dir / "sharded" / id / "labels.json");
  }
  EXPECT_EQ(lastStatuses(dir / "sharded").size(), 4u);

  // A rerun finds everything done: mesh, models and options unchanged.
  const auto before = fs::last_write_time(dir / "one" / "stove_s31_00000" / "labels.json");
  r = runSagrid(annotate(dir / "in", dir / "one"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("annotated 0 of 4 objects (4 up-to-date"));
  EXPECT_EQ(fs::last_write_time(dir / "one" / "stove_s31_00000" / "labels.json"), before);
  // Other options redo them.
  r = runSagrid(annotate(dir / "in", dir / "one", " --instances single --shard 0/2"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("annotated " + std::to_string(perShard[0]) + " of " +
                                  std::to_string(perShard[0]) + " objects (0 up-to-date"));
}

TEST(AnnotateBatchCli, CuratedLabelsAreKeptUnlessForced) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 32}}, gen::MeshFormat::Obj, dir / "in");
  ASSERT_EQ(runSagrid(annotate(dir / "in", dir / "out")).exitCode, 0);
  const fs::path file = dir / "out" / "stove_s32_00000" / "labels.json";
  ObjectLabels labels = readLabels(file);
  ASSERT_FALSE(labels.affordances.empty());
  labels.affordances[0].status = AffordanceStatus::Edited;
  labels.affordances[0].position += Eigen::Vector3f(0.01f, 0, 0);
  writeLabels(file, labels);
  const std::string curated = test::runCommand("cat " + q(file)).output;

  // Not even other options overwrite a person's work.
  auto r = runSagrid(annotate(dir / "in", dir / "out", " --instances single"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("annotated 0 of 1 objects (0 up-to-date, 1 curated kept"));
  EXPECT_EQ(test::runCommand("cat " + q(file)).output, curated);
  EXPECT_EQ(lastStatuses(dir / "out").at("stove_s32_00000"), "curated");

  r = runSagrid(annotate(dir / "in", dir / "out", " --force"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("annotated 1 of 1 objects"));
  for (const auto& a : readLabels(file).affordances)
    EXPECT_EQ(a.status, AffordanceStatus::Predicted);
}

TEST(AnnotateBatchCli, TwoTasksOnOneOutputAnnotateEachObjectOnce) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 33}, {"sink", 2, 33}}, gen::MeshFormat::Obj, dir / "in");
  const std::string one = q(test::sagridBinary()) + " " + annotate(dir / "in", dir / "out");
  const auto r = runCommand("(" + one + " > " + q(dir / "a.log") + " 2>&1 & " + one + " > " +
                            q(dir / "b.log") + " 2>&1 & wait)");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto lines = readManifest(dir / "out" / kRunManifestFile);
  EXPECT_EQ(lines.size(), 8u);  // every object once from each task
  std::map<std::string, int> annotated;
  for (const auto& l : lines) {
    const std::string status = l.at("status");
    EXPECT_TRUE(status == "annotated" || status == "busy" || status == "up-to-date") << l.dump();
    if (status == "annotated") ++annotated[l.at("object")];
  }
  ASSERT_EQ(annotated.size(), 4u);
  for (const auto& [id, n] : annotated) {
    EXPECT_EQ(n, 1) << id << " annotated by both tasks";
    EXPECT_NO_THROW(readLabels(dir / "out" / id / "labels.json"));
  }
}

// Runs `script` in a private mount namespace (the tmpfs mounts vanish with it).
test::CommandResult inMountNamespace(const std::string& script) {
  return runCommand("unshare --mount sh -ec " + shellQuote(script));
}

TEST(AnnotateBatchCli, AReadOnlyOrFullOutputIsOneClearErrorAndNoHalfWrittenLabels) {
  const fs::path dir = test::freshTempDir();
  if (inMountNamespace("true").exitCode != 0)
    GTEST_SKIP() << "needs a private mount namespace (unshare --mount) to mount a small tmpfs";
  gen::generateDataset({{"stove", 2, 34}}, gen::MeshFormat::Obj, dir / "in");
  const std::string sagrid = q(test::sagridBinary()) + " ";
  const fs::path out = dir / "out";
  fs::create_directories(out);

  auto r = inMountNamespace("mount -t tmpfs -o ro tmpfs " + q(out) + "; " + sagrid +
                            annotate(dir / "in", out / "labels"));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("labels: cannot create the output folder: Read-only file system"));

  // Full from the start: the probe write fails before any object.
  r = inMountNamespace("mount -t tmpfs -o size=64k tmpfs " + q(out) +
                       "; dd if=/dev/zero of=" + q(out / "fill") +
                       " bs=4096 2>/dev/null || true; " + sagrid + annotate(dir / "in", out));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("out: the output folder cannot be written"));
  EXPECT_THAT(r.output, AnyOf(HasSubstr("No space left on device"), HasSubstr("disk full")));

  // Full after one page: whatever fails (a labels file, the manifest) stops the batch with the
  // reason, and every labels file left is complete, with no temporary beside it.
  r = inMountNamespace("mount -t tmpfs -o size=64k tmpfs " + q(out) +
                       "; dd if=/dev/zero of=" + q(out / "fill") +
                       " bs=4096 2>/dev/null || true; truncate -s -4096 " + q(out / "fill") + "; " +
                       sagrid + annotate(dir / "in", out) + " && exit 9; echo EXIT=$?; find " +
                       q(out) + " -type f -name '*.json' -exec cat {} + > " +
                       q(dir / "labels.cat") + "; find " + q(out) + " -type f | sort");
  EXPECT_THAT(r.output, HasSubstr("EXIT=1")) << r.output;
  EXPECT_THAT(r.output, AnyOf(HasSubstr("No space left on device"), HasSubstr("disk full")));
  EXPECT_THAT(r.output, Not(HasSubstr(".tmp"))) << r.output;
  const std::string written = test::runCommand("cat " + q(dir / "labels.cat")).output;
  if (!written.empty()) EXPECT_NO_THROW((void)nlohmann::json::parse(written)) << written;
}

// The time limit itself is tested with a task that hangs (BatchRunner tests); since the readers
// refuse non-regular files (atomic_file), a FIFO now fails at once instead of at the limit.
TEST(AnnotateBatchCli, AFifoNamedLikeAMeshFailsAloneRefusedOrAtTheTimeLimit) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 35}}, gen::MeshFormat::Obj, dir / "in");
  // A FIFO named like a mesh: opening it blocks forever (a stalled network mount looks the same).
  ASSERT_EQ(::mkfifo((dir / "hang.obj").c_str(), 0644), 0);
  std::ofstream(dir / "objects.txt") << "hang.obj\nin/stove_s35_00000/mesh.obj\n";
  const auto r = runSagrid("annotate --list " + q(dir / "objects.txt") + " --out " +
                           q(dir / "out") + kFast + " --time-limit 3");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("hang.obj: failed"));
  EXPECT_THAT(r.output, HasSubstr("annotated 1 of 2 objects"));
  const auto statuses = lastStatuses(dir / "out");
  EXPECT_EQ(statuses.at("hang"), "failed");
  EXPECT_EQ(statuses.at("stove_s35_00000"), "annotated");
}

TEST(AnnotateBatchCli, AWorkerThatStopsMidObjectFailsThatObjectAtTheTimeLimit) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 3, 37}}, gen::MeshFormat::Obj, dir / "in");
  // Once the first object has started (its progress line), the worker is frozen with SIGSTOP: to
  // the batch it is an importer that never returns. The limit leaves a loaded machine's slowest
  // real object (a fresh worker's first, ~3 s at load 15 on 2 cores) well inside it.
  const std::string script =
      q(test::sagridBinary()) + " " + annotate(dir / "in", dir / "out", " --time-limit 8") + " > " +
      q(dir / "run.log") +
      " 2>&1 & parent=$!; "
      "for i in $(seq 600); do grep -q stove_s37 " +
      q(dir / "run.log") +
      " && break; sleep 0.05; done; "
      "worker=$(pgrep -P $parent | head -n 1); kill -STOP $worker; wait $parent; echo EXIT=$?; "
      "cat " +
      q(dir / "run.log");
  const auto r = runCommand("bash -c " + shellQuote(script));
  EXPECT_THAT(r.output, HasSubstr("EXIT=0"));
  EXPECT_THAT(r.output, HasSubstr("no result within the time limit of 8 s"));
  EXPECT_THAT(r.output, HasSubstr("annotated 2 of 3 objects"));
  std::size_t failed = 0;
  for (const auto& [id, status] : lastStatuses(dir / "out")) failed += status == "failed";
  EXPECT_EQ(failed, 1u) << r.output;
}

TEST(AnnotateBatchCli, FilterListsTheCandidatesThatAnnotateTakes) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 36}, {"sink", 2, 36}}, gen::MeshFormat::Obj, dir / "in");
  auto r = runSagrid("filter " + q(dir / "in") + " --like stove --top 2 --models " + kModels +
                     " --list-out " + q(dir / "stoves.txt"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("0 descriptors from the cache"));
  const std::string list = runCommand("cat " + q(dir / "stoves.txt")).output;
  EXPECT_THAT(list, HasSubstr("stove_s36_00000\t"));
  EXPECT_THAT(list, HasSubstr("stove_s36_00001\t"));
  EXPECT_THAT(list, Not(HasSubstr("sink")));

  // A second pass reads every descriptor from the cache.
  r = runSagrid("filter " + q(dir / "in") + " --like stove --models " + kModels);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("4 of 4 objects ranked (4 descriptors from the cache)"));

  r = runSagrid(annotate(dir / "stoves.txt", dir / "out"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("annotated 2 of 2 objects"));
  EXPECT_EQ(readLabels(dir / "out" / "stove_s36_00000" / "labels.json").object.category, "stove");
}

}  // namespace
}  // namespace sagrid
