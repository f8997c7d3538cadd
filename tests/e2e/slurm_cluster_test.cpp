// The Slurm array job for real (issue 13): a one-node cluster started on this machine from
// Debian's slurm-wlm and munge (packaging/slurm/local_cluster.sh), the job template
// packaging/slurm/annotate.sbatch submitted as `sbatch --wait --array=0-3`, the merged output
// compared with a one-process run, one task killed midway and a resubmission that completes only
// what it left undone. Without the packages the test is skipped; with them, anything that does
// not work fails it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <set>
#include <thread>

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
using test::shellQuote;
using ::testing::HasSubstr;

const fs::path kSlurmDir = fs::path(SAGRID_SOURCE_DIR) / "packaging" / "slurm";

std::string q(const fs::path& p) { return test::quotedPath(p); }

bool slurmInstalled() {
  return runCommand(
             "command -v sbatch && test -x /usr/sbin/slurmctld && test -x /usr/sbin/slurmd "
             "&& test -x /usr/sbin/munged")
             .exitCode == 0;
}

class SlurmClusterSlow : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!slurmInstalled())
      GTEST_SKIP() << "slurm-wlm and munge are not installed (packaging/install_deps.sh installs "
                      "them)";
    dir = test::freshTempDir();
    const auto r = runCommand(q(kSlurmDir / "local_cluster.sh") + " start " + q(dir / "cluster"));
    ASSERT_EQ(r.exitCode, 0) << r.output << logs();
    started = true;
    env = "SLURM_CONF=" + q(dir / "cluster" / "slurm.conf") + " SAGRID=" + q(test::sagridBinary()) +
          " ";
  }
  void TearDown() override {
    if (started) {
      const auto r = runCommand(q(kSlurmDir / "local_cluster.sh") + " stop " + q(dir / "cluster"));
      EXPECT_EQ(r.exitCode, 0) << r.output;
    }
  }
  std::string logs() const {
    return runCommand("tail -n 20 " + q(dir / "cluster" / "log") + "/*.log " + q(dir / "jobs") +
                      "/*.out 2>&1")
        .output;
  }
  // sbatch with the template; `options` go before the script (e.g. --wait), `args` after it.
  test::CommandResult submit(const std::string& options, const fs::path& out) {
    fs::create_directories(dir / "jobs");
    return runCommand(env + "sbatch --array=0-3 --output=" + q(dir / "jobs" / "%A_%a.out") + " " +
                      options + " " + q(kSlurmDir / "annotate.sbatch") + " " + q(dir / "in") + " " +
                      q(out) + " --symmetries 1 --models " +
                      q(fs::path(SAGRID_SOURCE_DIR) / "resources" / "models"));
  }
  fs::path dir;
  std::string env;
  bool started = false;
};

std::map<std::string, nlohmann::json> latest(const fs::path& out) {
  return latestByObject(readManifest(out / kRunManifestFile));
}

TEST_F(SlurmClusterSlow, ArrayJobEqualsOneProcessAndAResubmissionCompletesOnlyWhatWasKilled) {
  // Shards of 4 by id hash: 0 {sink 0, sink 2}, 1 {stove 0, sink 1}, 2 {stove 4}, 3 {stove 1-3}.
  const auto objects =
      gen::generateDataset({{"stove", 5, 41}, {"sink", 3, 41}}, gen::MeshFormat::Obj, dir / "in");
  // One thread, as each array task has (--cpus-per-task=1): the same summation order, so the
  // same numbers.
  auto r = runCommand("SAGRID_THREADS=1 " + q(test::sagridBinary()) + " annotate " + q(dir / "in") +
                      " --out " + q(dir / "one") + " --symmetries 1 --models " +
                      q(fs::path(SAGRID_SOURCE_DIR) / "resources" / "models"));
  ASSERT_EQ(r.exitCode, 0) << r.output;

  // 1. The whole array, waited for: the merged output is the one-process output.
  r = submit("--wait", dir / "array");
  ASSERT_EQ(r.exitCode, 0) << r.output << logs();
  const auto merged = latest(dir / "array");
  ASSERT_EQ(merged.size(), objects.size()) << logs();
  std::set<std::string> shards;
  for (const auto& o : objects) {
    const auto& line = merged.at(o.id);
    EXPECT_EQ(line.at("status"), "annotated") << line.dump();
    shards.insert(line.at("shard").get<std::string>());
    expectSameLabels(dir / "one" / o.id / "labels.json", dir / "array" / o.id / "labels.json");
  }
  EXPECT_EQ(shards, (std::set<std::string>{"0/4", "1/4", "2/4", "3/4"}));
  EXPECT_EQ(readManifest(dir / "array" / kRunManifestFile).size(), objects.size());

  // 2. Task 3 (three objects) is cancelled once it has finished its first object.
  r = submit("--parsable", dir / "killed");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string job = r.output.substr(0, r.output.find_first_of(";\n"));
  bool cancelled = false;
  for (int i = 0; i < 600 && !cancelled; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    if (!fs::exists(dir / "killed" / kRunManifestFile)) continue;
    for (const auto& line : readManifest(dir / "killed" / kRunManifestFile)) {
      if (line.value("shard", "") != "3/4") continue;
      const auto c = runCommand(env + "scancel " + job + "_3");
      ASSERT_EQ(c.exitCode, 0) << c.output;
      cancelled = true;
      break;
    }
  }
  ASSERT_TRUE(cancelled) << "task 3 never finished an object\n" << logs();
  // Wait for the other tasks to end.
  for (int i = 0; i < 600; ++i) {
    if (runCommand(env + "squeue -h -j " + job).output.find(job) == std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  std::set<std::string> missing;
  for (const auto& o : objects)
    if (!fs::exists(dir / "killed" / o.id / "labels.json")) missing.insert(o.id);
  ASSERT_FALSE(missing.empty()) << "task 3 finished before it was cancelled\n" << logs();
  const std::set<std::string> task3{"stove_s41_00001", "stove_s41_00002", "stove_s41_00003"};
  for (const auto& id : missing) EXPECT_TRUE(task3.count(id)) << id << " is not task 3's";
  const std::size_t linesBefore = readManifest(dir / "killed" / kRunManifestFile).size();

  // 3. The same submission again: only the missing objects are annotated.
  r = submit("--wait", dir / "killed");
  ASSERT_EQ(r.exitCode, 0) << r.output << logs();
  const auto lines = readManifest(dir / "killed" / kRunManifestFile);
  ASSERT_EQ(lines.size(), linesBefore + objects.size());
  std::set<std::string> redone;
  for (std::size_t i = linesBefore; i < lines.size(); ++i) {
    const std::string status = lines[i].at("status");
    if (status == "annotated")
      redone.insert(lines[i].at("object").get<std::string>());
    else
      EXPECT_EQ(status, "up-to-date") << lines[i].dump();
  }
  EXPECT_EQ(redone, missing);
  for (const auto& o : objects)
    expectSameLabels(dir / "one" / o.id / "labels.json", dir / "killed" / o.id / "labels.json");
}

}  // namespace
}  // namespace sagrid
