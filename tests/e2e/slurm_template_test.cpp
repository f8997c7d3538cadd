// packaging/slurm/annotate.sbatch outside a cluster: without Slurm its error says what to install,
// outside an array it says how to submit, and a missing binary is named.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::runCommand;
using test::shellQuote;
using ::testing::HasSubstr;

const std::string kTemplate =
    shellQuote((fs::path(SAGRID_SOURCE_DIR) / "packaging" / "slurm" / "annotate.sbatch").string());

TEST(SlurmTemplate, WithoutSlurmTheErrorSaysWhatToInstall) {
  const fs::path empty = test::freshTempDir();  // a PATH with no sbatch on it
  const auto r = runCommand("env -i PATH=" + shellQuote(empty.string()) + " /bin/bash " +
                            kTemplate + " in out");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("Slurm is not installed here (no sbatch)"));
  EXPECT_THAT(r.output, HasSubstr("apt-get install slurm-client"));
  EXPECT_THAT(r.output, HasSubstr("apt-get install slurm-wlm munge"));
}

TEST(SlurmTemplate, OutsideAnArrayOrWithoutTheBinaryItSaysWhatToDo) {
  const fs::path dir = test::freshTempDir();
  // sbatch present (a stand-in), but not in an array task.
  const auto fake = dir / "sbatch";
  runCommand("printf '#!/bin/sh\\n' > " + shellQuote(fake.string()) + " && chmod +x " +
             shellQuote(fake.string()));
  auto r = runCommand("env -i PATH=" + shellQuote(dir.string()) + ":/usr/bin:/bin /bin/bash " +
                      kTemplate + " in out");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("not running as a Slurm array task"));
  EXPECT_THAT(r.output, HasSubstr("sbatch --array=0-N"));

  r = runCommand(
      "env -i PATH=/usr/bin:/bin SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=2 "
      "SAGRID=/nonexistent/sagrid /bin/bash " +
      kTemplate + " in out");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("cannot run '/nonexistent/sagrid'"));

  r = runCommand(
      "env -i PATH=/usr/bin:/bin SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=2 "
      "/bin/bash " +
      kTemplate + " in");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("usage: sbatch --array=0-N annotate.sbatch INPUT OUT"));
}

TEST(SlurmTemplate, TasksOfAnArrayStartingAtOneAreShardsFromZero) {
  const fs::path dir = test::freshTempDir();
  const auto fake = dir / "sagrid";  // prints the arguments it was given
  runCommand("printf '#!/bin/sh\\necho \"$@\"\\n' > " + shellQuote(fake.string()) +
             " && chmod +x " + shellQuote(fake.string()));
  const auto r = runCommand(
      "env -i PATH=/usr/bin:/bin SLURM_ARRAY_TASK_ID=4 "
      "SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=4 SAGRID=" +
      shellQuote(fake.string()) + " /bin/bash " + kTemplate + " in out --force");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("annotate in --out out --shard 3/4 --force"));
}

}  // namespace
}  // namespace sagrid
