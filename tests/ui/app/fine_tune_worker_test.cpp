// The GUI's Train panel fine-tunes the models it loaded: same core call as `sagrid train --init`.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/model/model_card.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"
#include "ui/app/training_worker.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

const fs::path kShipped = fs::path(SAGRID_SOURCE_DIR) / "resources" / "models";

void generateStove(const fs::path& out, int seed) {
  ASSERT_EQ(sagrid::test::runSagrid("generate --category stove --count 1 --seed " +
                                    std::to_string(seed) + " --out " +
                                    sagrid::test::shellQuote(out.string()))
                .exitCode,
            0);
}

// A one-epoch fine-tune of the shipped stove models on `dir`/train into `dir`/models, without the
// bench replay (the CLI exercises it; this keeps the test fast), to its end.
TrainingStatus fineTune(const fs::path& dir, const fs::path& heldOut, int seconds,
                        bool keepInit = false) {
  TrainingWorker worker;
  TrainingRequest request;
  request.dataset = dir / "train";
  request.category = "stove";
  request.outDir = dir / "models";
  request.epochs = 1;
  request.initDir = kShipped;
  request.replay = false;
  request.heldOut = heldOut;
  request.keepInitNetworks = keepInit;
  worker.start(request);
  for (int i = 0; i < 20 * seconds && worker.running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(worker.running()) << "fine-tune did not finish in " << seconds << " s";
  return worker.status();
}

TEST(FineTuneWorker, InitsFromTheLoadedModels) {
  const auto dir = sagrid::test::freshTempDir();
  generateStove(dir / "train", 31);
  const fs::path shipped = kShipped;
  const TrainingStatus status = fineTune(dir, {}, 60);
  ASSERT_TRUE(status.error.empty()) << status.error;
  // One object, one source: nothing can judge, and each model's line says so.
  ASSERT_EQ(status.verdicts.size(), 2u);
  for (const auto& verdict : status.verdicts)
    EXPECT_NE(
        verdict.find("unguarded: the training set's objects of its type come from one source"),
        std::string::npos)
        << verdict;
  for (const char* name : {"stove.heatsource", "stove.togglebutton"}) {
    const auto card = model::readModelCard(dir / "models" / (std::string(name) + ".json"));
    const auto init = model::readModelCard(shipped / (std::string(name) + ".json"));
    ASSERT_TRUE(card.training.contains("init")) << name;
    EXPECT_EQ(card.training.at("init").at("weights_sha256"), init.weightsSha256);
    EXPECT_DOUBLE_EQ(card.training.at("learning_rate").get<double>(), 1e-3);
    EXPECT_EQ(card.architecture, init.architecture);
  }
}

// "keep the loaded networks": each fine-tuned network joins the loaded model's networks (the
// knob model's member trained apart stays), under the loaded card.
TEST(FineTuneWorker, KeepsTheLoadedNetworksBesideTheFineTune) {
  const auto dir = sagrid::test::freshTempDir();
  generateStove(dir / "train", 31);
  const TrainingStatus status = fineTune(dir, {}, 60, true);
  ASSERT_TRUE(status.error.empty()) << status.error;
  for (const char* name : {"stove.heatsource", "stove.togglebutton"}) {
    const auto card = model::readModelCard(dir / "models" / (std::string(name) + ".json"));
    const auto init = model::readModelCard(kShipped / (std::string(name) + ".json"));
    EXPECT_EQ(card.weightsSha256, init.weightsSha256) << name;
    ASSERT_EQ(card.ensemble.size(), init.ensemble.size() + 1) << name;
    for (std::size_t i = 0; i < init.ensemble.size(); ++i)
      EXPECT_EQ(card.ensemble[i].sha256, init.ensemble[i].sha256) << name;
    EXPECT_EQ(card.training["ensemble"].back()["role"], "fine-tune") << name;
  }
}

// Guarded (issue 40): with held-out curated objects each fine-tuned model is judged there; the
// panel shows one verdict per model and the models folder holds, per model, the better one.
TEST(FineTuneWorker, GuardsEachModelOnHeldOutObjects) {
  const auto dir = sagrid::test::freshTempDir();
  generateStove(dir / "train", 31);
  generateStove(dir / "held-out", 32);
  const fs::path shipped = kShipped;
  const TrainingStatus status = fineTune(dir, dir / "held-out", 180);
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 2u);
  for (const auto& verdict : status.verdicts) EXPECT_NE(verdict.find("held-out object"), std::string::npos) << verdict;
  for (const char* name : {"stove.heatsource", "stove.togglebutton"}) {
    const bool refused = fs::exists(dir / "models" / "refused" / (std::string(name) + ".pt"));
    const auto card = model::readModelCard(dir / "models" / (std::string(name) + ".json"));
    const auto init = model::readModelCard(shipped / (std::string(name) + ".json"));
    // Refused: the shipped model stays; adopted: the fine-tune of it.
    EXPECT_EQ(card.weightsSha256 == init.weightsSha256, refused) << name;
  }
  EXPECT_FALSE(fs::exists(dir / "models" / ".candidate.stove.heatsource"));
}

// Without a held-out folder the training set's sources judge: each model's fine-tune is repeated
// with each source left out, one verdict per model says so, and the models folder holds, per
// model, the adopted fine-tune or the loaded model.
TEST(FineTuneWorker, GuardsEachModelBySourceWithoutAHeldOutFolder) {
  const auto dir = sagrid::test::freshTempDir();
  ASSERT_EQ(sagrid::test::runSagrid("generate --category stove --count 2 --seed 33 --out " +
                                    sagrid::test::shellQuote((dir / "train").string()))
                .exitCode,
            0);
  sagrid::test::assignSources(dir / "train", {"repo-a", "repo-b"});
  const TrainingStatus status = fineTune(dir, {}, 300);
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 2u);
  for (const auto& verdict : status.verdicts)
    EXPECT_NE(verdict.find("on 2 curated object(s) of 2 sources"), std::string::npos) << verdict;
  std::ifstream log(dir / "models" / "guard.jsonl");
  std::string line;
  int lines = 0;
  while (std::getline(log, line)) {
    const auto verdict = nlohmann::json::parse(line);
    const std::string name = verdict.at("model");
    EXPECT_EQ(verdict.at("judged_by_source"), true) << name;
    const auto card = model::readModelCard(dir / "models" / (name + ".json"));
    const auto init = model::readModelCard(kShipped / (name + ".json"));
    EXPECT_EQ(card.weightsSha256 == init.weightsSha256, !verdict.at("adopted").get<bool>()) << name;
    ++lines;
  }
  EXPECT_EQ(lines, 2);
  EXPECT_FALSE(fs::exists(dir / "models" / ".guard-by-source.stove.heatsource"));
  EXPECT_FALSE(fs::exists(dir / "models" / ".candidate.stove.togglebutton"));
}

}  // namespace
}  // namespace sagrid::ui
