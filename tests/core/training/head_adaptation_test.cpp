// Fine-tuning the head only (issue 40: a few real objects must not undo what the bench taught):
// the earlier layers and every batch-norm statistic stay exactly the init model's, the last layer
// and the head change; fine-tuning everything changes the first layer and the statistics too.
// Tiny generated stoves on a 16^3 grid.
#include <gtest/gtest.h>

#include "core/generate/dataset_generator.h"
#include "core/model/affordance_model_impl.h"
#include "core/training/dataset_training.h"
#include "support/test_paths.h"
#include "support/tiny_training.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

constexpr const char* kModel = "stove.heatsource";

DatasetTrainingOptions tinyOptions(const fs::path& data, const fs::path& out) {
  return test::tinyTraining(kModel, data, out, 2);
}

// Whether each named parameter or buffer of the two models' networks is equal.
std::map<std::string, bool> sameTensors(const fs::path& cardA, const fs::path& cardB) {
  model::AffordanceModel a = model::AffordanceModel::load(cardA), b = model::AffordanceModel::load(cardB);
  std::map<std::string, bool> same;
  const auto tensorsOf = [](model::AffordanceModel& m) {
    auto all = m.impl().net->named_parameters();
    for (const auto& buffer : m.impl().net->named_buffers()) all.insert(buffer.key(), buffer.value());
    return all;
  };
  const auto ta = tensorsOf(a), tb = tensorsOf(b);
  for (const auto& t : ta) same[t.key()] = torch::equal(t.value(), tb[t.key()]);
  return same;
}

TEST(HeadAdaptation, OnlyTheLastLayerAndTheHeadChange) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 51}}, gen::MeshFormat::Obj, dir / "bench");
  gen::generateDataset({{"stove", 2, 52}}, gen::MeshFormat::Obj, dir / "real");
  const auto base = trainFromDataset(tinyOptions(dir / "bench", dir / "base"));

  DatasetTrainingOptions head = tinyOptions(dir / "real", dir / "head");
  head.init = dir / "base";
  head.training.adapted = model::AdaptedPart::Head;
  const auto headTuned = trainFromDataset(head);
  std::map<std::string, bool> same = sameTensors(base.cardFile, headTuned.cardFile);
  for (const char* name : {"layer0_weight", "layer0_bn_weight", "layer0_bn_bias", "layer0_bn_running_mean",
                           "layer0_bn_running_var", "layer1_bn_running_mean", "layer1_bn_running_var"})
    EXPECT_TRUE(same.at(name)) << name;
  for (const char* name : {"layer1_weight", "layer1_bn_weight", "layer1_bn_bias", "head_weight", "head_bias"})
    EXPECT_FALSE(same.at(name)) << name;
  EXPECT_EQ(model::readModelCard(headTuned.cardFile).training.at("adapted"), "head");

  DatasetTrainingOptions everything = tinyOptions(dir / "real", dir / "everything");
  everything.init = dir / "base";
  same = sameTensors(base.cardFile, trainFromDataset(everything).cardFile);
  for (const char* name : {"layer0_weight", "layer0_bn_running_mean", "head_weight"})
    EXPECT_FALSE(same.at(name)) << name;
}

}  // namespace
}  // namespace sagrid
