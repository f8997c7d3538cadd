// Guarded updates: of two models of one type, the guard adopts the one with the lower error on
// held-out objects, beyond the noise of their per-object differences, and refuses the other,
// whichever is called current; a gain within its noise is refused; a refused candidate goes
// aside with the current model kept in place, and every verdict is logged. Tiny models on a 16^3
// grid trained for this test.
#include "core/training/guarded_update.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/error.h"

#include "core/common/atomic_file.h"
#include "core/generate/dataset_generator.h"
#include "core/model/model_files.h"
#include "core/training/dataset_training.h"
#include "support/test_paths.h"
#include "support/tiny_training.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
constexpr const char* kModel = "stove.heatsource";

using test::tinyFeatures;

void trainTiny(const fs::path& data, const fs::path& out, unsigned seed, int epochs) {
  DatasetTrainingOptions o = test::tinyTraining(kModel, data, out, epochs);
  o.training.seed = seed;
  o.training.learningRate = 1e-2;
  trainFromDataset(o);
}

TEST(GuardedUpdate, AdoptsTheBetterModelAndRefusesTheWorse) {
  const fs::path dir = test::freshTempDir();
  // A model that learned heat sources on the knob against one that learned them where they are,
  // judged on the stoves both trained on (a test of the guard, not of how tiny models carry to
  // other objects): apart on every one, by more than the noise of six.
  gen::generateDataset({{"stove", 6, 21}}, gen::MeshFormat::Obj, dir / "train");
  gen::generateDataset({{"stove", 6, 21}}, gen::MeshFormat::Obj, dir / "held-out");
  gen::generateDataset({{"stove", 6, 21}}, gen::MeshFormat::Obj, dir / "train-knob");
  test::heatSourcesOnTheKnob(dir / "train-knob");
  trainTiny(dir / "train-knob", dir / "a", 1, 40);
  trainTiny(dir / "train", dir / "b", 2, 40);

  GuardOptions ab{dir / "a", dir / "b", kModel, dir / "held-out", {}, {}, tinyFeatures()};
  GuardOptions ba{dir / "b", dir / "a", kModel, dir / "held-out", {}, {}, tinyFeatures()};
  const GuardVerdict forward = judgeUpdate(ab), backward = judgeUpdate(ba);
  EXPECT_EQ(forward.objects, 6u);
  ASSERT_NE(forward.candidateError, forward.currentError);
  EXPECT_DOUBLE_EQ(forward.candidateError, backward.currentError);  // the same model either way
  EXPECT_NE(forward.adopted, backward.adopted) << forward.reason << " / " << backward.reason;
  const GuardVerdict& adopted = forward.adopted ? forward : backward;
  EXPECT_LT(adopted.candidateError, adopted.currentError);
  // Adopted only beyond the standard error of the per-object differences.
  EXPECT_LT(adopted.candidateError, adopted.currentError - adopted.pairedNoise);
  EXPECT_NE(adopted.reason.find("adopted"), std::string::npos);
  EXPECT_NE(adopted.reason.find("noise"), std::string::npos);
  // The current model's figures, when the caller has them, are not evaluated again: they decide.
  const HeldOutError current = heldOutError(ab.currentDir, ab);
  ASSERT_EQ(current.byObject.size(), 6u);
  const GuardVerdict again = judgeUpdate(ab, current);
  EXPECT_EQ(again.adopted, forward.adopted);
  EXPECT_DOUBLE_EQ(again.candidateError, forward.candidateError);
  HeldOutError perfect = current;  // nothing beats 0
  for (auto& [id, error] : perfect.byObject) error = 0;
  EXPECT_FALSE(judgeUpdate(ab, perfect).adopted);
  // Better than the candidate on one object alone, by a millimetre: within its noise, refused.
  HeldOutError aHairWorse = heldOutError(ab.candidateDir, ab);
  aHairWorse.byObject.begin()->second += 0.001;
  const GuardVerdict hair = judgeUpdate(ab, aHairWorse);
  EXPECT_FALSE(hair.adopted);
  EXPECT_NE(hair.reason.find("better by less than its noise"), std::string::npos) << hair.reason;
  // A figure without its objects pairs none: nothing is judged and the current model stays.
  const GuardVerdict unpaired = judgeUpdate(ab, HeldOutError{1.0, 6, {}});
  EXPECT_FALSE(unpaired.adopted);
  EXPECT_NE(unpaired.reason.find("no object judged by both"), std::string::npos) << unpaired.reason;

  // The refused one in effect: it goes aside, the current model is what OUT holds.
  const GuardVerdict& refused = forward.adopted ? backward : forward;
  const GuardOptions& refusedOptions = forward.adopted ? ba : ab;
  const fs::path candidate = dir / "candidate";
  model::copyModelFiles(refusedOptions.candidateDir, candidate, kModel);
  GuardOptions applied = refusedOptions;
  applied.candidateDir = candidate;
  applyVerdict(refused, applied, dir / "out");
  const std::string pt = std::string(kModel) + ".pt";
  EXPECT_EQ(readFileBytes(dir / "out" / pt), readFileBytes(refusedOptions.currentDir / pt));
  EXPECT_EQ(readFileBytes(dir / "out" / "refused" / pt), readFileBytes(refusedOptions.candidateDir / pt));
  EXPECT_FALSE(fs::exists(candidate / pt));
  std::ifstream log(dir / "out" / "guard.jsonl");
  std::string line;
  ASSERT_TRUE(std::getline(log, line));
  EXPECT_NE(line.find("\"adopted\":false"), std::string::npos) << line;
}

TEST(GuardedUpdate, WithoutHeldOutObjectsOfItsTypeTheCurrentModelStays) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 31}}, gen::MeshFormat::Obj, dir / "train");
  gen::generateDataset({{"sink", 2, 32}}, gen::MeshFormat::Obj, dir / "sinks");
  trainTiny(dir / "train", dir / "a", 1, 1);
  trainTiny(dir / "train", dir / "b", 2, 1);
  const GuardVerdict v = judgeUpdate({dir / "a", dir / "b", kModel, dir / "sinks", {}, {}, tinyFeatures()});
  EXPECT_FALSE(v.adopted);
  EXPECT_EQ(v.objects, 0u);
  EXPECT_NE(v.reason.find("no held-out object"), std::string::npos);
}

TEST(GuardedUpdate, AModelsFolderMixingFeatureSetupsIsRefusedBeforeTraining) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 33}}, gen::MeshFormat::Obj, dir / "train");
  gen::generateDataset({{"stove", 1, 34}}, gen::MeshFormat::Obj, dir / "held-out");
  trainTiny(dir / "train", dir / "current", 1, 1);
  // A second model of another grid size beside it (an older version left in the folder).
  nlohmann::json card = nlohmann::json::parse(readFileBytes(dir / "current" / "stove.heatsource.json"));
  card["name"] = "stove.togglebutton";
  card["type"] = "togglebutton";
  card["grid_resolution"] = 32;
  writeFileAtomic(dir / "current" / "stove.togglebutton.json", card.dump());
  fs::copy_file(dir / "current" / "stove.heatsource.pt", dir / "current" / "stove.togglebutton.pt");
  const GuardOptions guard{dir / "current", dir / "candidate", kModel, dir / "held-out", {}, {}, tinyFeatures()};
  try {
    checkGuardedUpdate(guard, {dir / "train"});
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("does not load as one set"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find((dir / "current").string()), std::string::npos) << e.what();
  }
  // One setup in the folder and sound data: no objection.
  fs::remove(dir / "current" / "stove.togglebutton.json");
  fs::remove(dir / "current" / "stove.togglebutton.pt");
  EXPECT_NO_THROW(checkGuardedUpdate(guard, {dir / "train"}));
}

}  // namespace
}  // namespace sagrid
