// `train --keep-init` (issue 40: a fine-tune on a few real objects that cannot forget what the
// init knew): the result keeps the init's network and card and adds the fine-tuned network beside
// it; fine-tuned again in place, the earlier fine-tune is replaced, not piled up. Tiny generated
// stoves on a 16^3 grid.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/generate/dataset_generator.h"
#include "core/model/affordance_model.h"
#include "core/model/model_ensemble.h"
#include "core/training/dataset_training.h"
#include "support/test_paths.h"
#include "support/tiny_training.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

constexpr const char* kModel = "stove.heatsource";

TEST(KeptInitNetworks, TheFineTuneJoinsTheInitNetworksAndReplacesTheEarlierOne) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 61}}, gen::MeshFormat::Obj, dir / "bench");
  gen::generateDataset({{"stove", 2, 62}}, gen::MeshFormat::Obj, dir / "real");
  const auto base = trainFromDataset(test::tinyTraining(kModel, dir / "bench", dir / "base"));

  DatasetTrainingOptions kept = test::tinyTraining(kModel, dir / "real", dir / "kept");
  kept.init = dir / "base";
  kept.keepInitNetworks = true;
  const auto first = trainFromDataset(kept);
  EXPECT_EQ(first.cardFile, dir / "kept" / (std::string(kModel) + ".json"));
  EXPECT_FALSE(first.recalibrated);
  const model::ModelCard card = model::readModelCard(first.cardFile);
  EXPECT_EQ(card.weightsSha256, base.card.weightsSha256);
  EXPECT_FLOAT_EQ(card.extraction.maxDistance, base.card.extraction.maxDistance);
  ASSERT_EQ(card.ensemble.size(), 1u);
  EXPECT_NE(card.ensemble[0].sha256, base.card.weightsSha256);
  EXPECT_EQ(card.training["ensemble"][0]["role"], model::kFineTuneRole);
  EXPECT_EQ(model::AffordanceModel::load(first.cardFile).networkCount(), 2u);
  EXPECT_TRUE(fs::exists(dir / "kept" / (std::string(kModel) + ".loss.csv")));
  for (const auto& entry : fs::directory_iterator(dir / "kept"))
    EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();  // no scratch left

  // Fine-tuned again from that model into its own folder: two networks still, a new fine-tune.
  kept.init = dir / "kept";
  kept.training.seed = 2;
  const auto second = trainFromDataset(kept);
  const model::ModelCard again = model::readModelCard(second.cardFile);
  EXPECT_EQ(again.weightsSha256, base.card.weightsSha256);
  ASSERT_EQ(again.ensemble.size(), 1u);
  EXPECT_NE(again.ensemble[0].sha256, card.ensemble[0].sha256);
  EXPECT_EQ(model::AffordanceModel::load(second.cardFile).networkCount(), 2u);
}

TEST(KeptInitNetworks, WithoutAnInitModelItIsRefusedBeforeAnythingTrains) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 63}}, gen::MeshFormat::Obj, dir / "real");
  DatasetTrainingOptions kept = test::tinyTraining(kModel, dir / "real", dir / "kept");
  kept.keepInitNetworks = true;
  try {
    trainFromDataset(kept);
    ADD_FAILURE() << "kept init networks without an init";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("--init"));
  }
  EXPECT_FALSE(fs::exists(dir / "kept"));
}

}  // namespace
}  // namespace sagrid
