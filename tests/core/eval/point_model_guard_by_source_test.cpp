// The point model's guard by source: the fine-tune is repeated with each fold of sources left out
// and judged on the left-out objects. Curated labels whose convention every source shares (heat
// sources on the knob, which the current model never learned) carry to the left-out source and
// are adopted; a convention one source alone has does not, and is refused. The current model's
// figure is its error on every curated object of the type; one source cannot judge. Tiny models on
// a 16^3 grid.
#include "core/eval/point_model_guard_by_source.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/dataset/dataset.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "support/test_paths.h"
#include "support/tiny_training.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
constexpr const char* kModel = "stove.heatsource";

struct Bench {
  fs::path dir, current;
  PointModelGuardBySource guard;
};

// Two curated folders of stoves (their folder names are their sources), a current model trained
// for `epochs` on four generated stoves and, with `curatedToo`, on the curated ones as well, and a
// fine-tune of it on the curated folders to guard.
Bench makeBench(int epochs, bool curatedToo) {
  Bench b;
  b.dir = test::freshTempDir();
  gen::generateDataset({{"stove", 4, 41}}, gen::MeshFormat::Obj, b.dir / "generated");
  gen::generateDataset({{"stove", 3, 42}}, gen::MeshFormat::Obj, b.dir / "repo-a");
  gen::generateDataset({{"stove", 3, 43}}, gen::MeshFormat::Obj, b.dir / "repo-b");
  const std::vector<TrainingDataSource> curated = {{b.dir / "repo-a", 1.0, "data", {}, {}},
                                                   {b.dir / "repo-b", 1.0, "data", {}, {}}};
  b.current = b.dir / "current";
  DatasetTrainingOptions current = test::tinyTraining(kModel, {}, b.current, epochs);
  current.datasets = {{b.dir / "generated", 1.0, "data", {}, {}}};
  if (curatedToo) current.datasets.insert(current.datasets.end(), curated.begin(), curated.end());
  trainFromDataset(current);
  b.guard.currentDir = b.current;
  b.guard.fineTune = test::tinyTraining(kModel, {}, b.dir / "candidate", 40);
  b.guard.fineTune.init = b.current;
  b.guard.fineTune.training.learningRate = 1e-2;
  b.guard.fineTune.datasets = curated;
  b.guard.workDir = b.dir / "work";
  return b;
}

// A current model that learned little from one epoch on four generated stoves: six more teach it,
// and every left-out stove says so (beyond the paired noise; with six epochs, one stove's 90 cm
// -> 4 cm made most of the gain, and the guard rightly refused it).
TEST(PointModelGuardBySource, AdoptsAFineTuneThatCarriesToTheLeftOutSource) {
  Bench b = makeBench(1, false);
  int foldsSeen = 0;
  b.guard.onFold = [&](int fold, int folds) {
    EXPECT_EQ(fold, ++foldsSeen);
    EXPECT_EQ(folds, 2);  // three asked for, two sources
  };
  const auto verdict = judgeUpdateBySource(b.guard);
  ASSERT_TRUE(verdict);
  EXPECT_EQ(foldsSeen, 2);
  EXPECT_TRUE(verdict->judgedBySource);
  EXPECT_EQ(verdict->folds, 2);
  EXPECT_EQ(verdict->sources, (std::vector<std::string>{"repo-a", "repo-b"}));
  EXPECT_EQ(verdict->objects, 6u);  // every curated stove, each judged once
  EXPECT_TRUE(verdict->adopted) << verdict->reason;
  EXPECT_LT(verdict->candidateError, verdict->currentError - verdict->pairedNoise);
  EXPECT_GT(verdict->pairedNoise, 0);
  EXPECT_NE(verdict->reason.find("6 curated object(s) of 2 sources"), std::string::npos)
      << verdict->reason;
  EXPECT_FALSE(fs::exists(b.guard.workDir));

  // The current model's figure is its error on all six, as the held-out guard measures it.
  const fs::path both = b.dir / "both";
  fs::create_directories(both);
  for (const char* repo : {"repo-a", "repo-b"})
    for (const auto& e : fs::directory_iterator(b.dir / repo))
      if (e.is_directory() && e.path().filename().string()[0] != '.')
        fs::create_directory_symlink(
            e.path(), both / (std::string(repo) + "-" + e.path().filename().string()));
  const HeldOutError all = heldOutError(
      b.current, {b.current, b.dir / "scratch", kModel, both, {}, {}, test::tinyFeatures()});
  EXPECT_EQ(all.objects, 6u);
  EXPECT_NEAR(all.error, verdict->currentError, 1e-6);
}

// A current model that knows the curated stoves, and one source that puts its heat sources on the
// knob: what that source teaches does not carry to the other.
TEST(PointModelGuardBySource, RefusesAFineTuneThatDoesNotCarry) {
  Bench b = makeBench(40, true);
  test::heatSourcesOnTheKnob(b.dir / "repo-b");
  const auto verdict = judgeUpdateBySource(b.guard);
  ASSERT_TRUE(verdict);
  EXPECT_FALSE(verdict->adopted) << verdict->reason;
  EXPECT_GT(verdict->candidateError, verdict->currentError);
  EXPECT_NE(verdict->reason.find("refused, current model kept"), std::string::npos)
      << verdict->reason;
}

TEST(PointModelGuardBySource, OneSourceCannotJudgeAndOneFoldIsAnError) {
  Bench b = makeBench(1, false);
  b.guard.fineTune.datasets.pop_back();  // repo-a alone
  EXPECT_FALSE(judgeUpdateBySource(b.guard));
  b.guard.folds = 1;
  EXPECT_THROW(judgeUpdateBySource(b.guard), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
