// Ensembles (core/model/model_ensemble.h): a card that lists more networks predicts the mean of
// their fields; members of another model, replaced member weights and ensembles that training
// would overwrite are refused with the file named. A fine-tune kept beside its init's networks
// replaces an earlier fine-tune and keeps the init's other members and card.
#include "core/model/model_ensemble.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/io/json_file.h"
#include "core/model/affordance_model.h"
#include "support/test_paths.h"
#include "support/untrained_models.h"

namespace sagrid::model {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

// Every voxel of a 5^3 grid occupied, channels (nx, ny, nz, a) varying smoothly.
FeatureGrid smallGrid() {
  FeatureGrid g;
  g.backend = "test";
  g.configHash = "test";
  g.resolution = 5;
  g.channels = 4;
  g.descriptor = {0.3f, 0.6f};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k) {
        g.voxels.push_back({i, j, k});
        g.values.insert(g.values.end(), {0.2f * i - 0.4f, 0.1f * j, -0.1f * k, 0.05f * (i + j)});
      }
  return g;
}

// An untrained network of `name` for smallGrid(), saved in its own folder; returns the card.
fs::path savedNetwork(const std::string& name, unsigned seed) {
  const fs::path dir = test::freshTempDir(name + "-" + std::to_string(seed));
  AffordanceModel model = test::untrainedModelFor(name, smallGrid(), seed);
  model.card().training = {{"command", "sagrid train --seed " + std::to_string(seed)}};
  model.save(dir / (name + ".json"));
  return dir / (name + ".json");
}

TEST(ModelEnsemble, PredictsTheMeanOfItsNetworksFields) {
  const fs::path card = savedNetwork("stove.togglebutton", 1);
  const fs::path other = savedNetwork("stove.togglebutton", 2);
  const FeatureGrid grid = smallGrid();
  const std::vector<float> a = AffordanceModel::load(card).predictDistances(grid);
  const std::vector<float> b = AffordanceModel::load(other).predictDistances(grid);
  ASSERT_NE(a, b);

  const fs::path copied = addEnsembleMember(card, other);
  EXPECT_EQ(copied, card.parent_path() / "stove.togglebutton.member1.pt");
  const AffordanceModel ensemble = AffordanceModel::load(card);
  EXPECT_EQ(ensemble.networkCount(), 2u);
  const std::vector<float> mean = ensemble.predictDistances(grid);
  ASSERT_EQ(mean.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(mean[i], 0.5f * (a[i] + b[i]), 1e-5f);

  // The card names the copy with its sha, records how the member was trained, and everything
  // that keys on the weights (annotation fingerprints, the evidence gate) sees a new identity.
  const ModelCard read = readModelCard(card);
  ASSERT_EQ(read.ensemble.size(), 1u);
  EXPECT_EQ(read.ensemble[0].file, "stove.togglebutton.member1.pt");
  EXPECT_EQ(read.ensemble[0].sha256, readModelCard(other).weightsSha256);
  EXPECT_EQ(read.training["ensemble"][0]["command"], "sagrid train --seed 2");
  EXPECT_NE(read.weightsIdentity(), read.weightsSha256);
  EXPECT_THAT(read.sourceTag(), HasSubstr("@" + read.weightsIdentity().substr(0, 8)));
  EXPECT_EQ(readModelCard(other).weightsIdentity(), readModelCard(other).weightsSha256);

  // A second member gets the next file name; the field is the mean of all three.
  const fs::path third = savedNetwork("stove.togglebutton", 3);
  EXPECT_EQ(addEnsembleMember(card, third).filename(), "stove.togglebutton.member2.pt");
  const std::vector<float> c = AffordanceModel::load(third).predictDistances(grid);
  const std::vector<float> mean3 = AffordanceModel::load(card).predictDistances(grid);
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_NEAR(mean3[i], (a[i] + b[i] + c[i]) / 3.0f, 1e-5f);
}

TEST(ModelEnsemble, AMemberOfAnotherModelOrTheSameWeightsIsRefused) {
  const fs::path card = savedNetwork("stove.togglebutton", 1);
  const std::string before = readFileBytes(card);
  const fs::path heat = savedNetwork("stove.heatsource", 2);
  try {
    addEnsembleMember(card, heat);
    ADD_FAILURE() << "another model was added";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), HasSubstr(heat.string()));
    EXPECT_THAT(e.what(), HasSubstr("stove.heatsource"));
  }
  EXPECT_THROW(addEnsembleMember(card, card), ModelError);
  // A member whose weights no longer match its own card is refused, naming its card.
  const fs::path damaged = savedNetwork("stove.togglebutton", 2);
  writeFileAtomic(damaged.parent_path() / "stove.togglebutton.pt", "not weights");
  try {
    addEnsembleMember(card, damaged);
    ADD_FAILURE() << "damaged member weights were added";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr(damaged.string()));
  }
  EXPECT_EQ(readFileBytes(card), before);
  EXPECT_FALSE(fs::exists(card.parent_path() / "stove.togglebutton.member1.pt"));
}

TEST(ModelEnsemble, ReplacedOrMissingMemberWeightsNameTheCard) {
  const fs::path card = savedNetwork("sink.fluidsource", 1);
  const fs::path copied = addEnsembleMember(card, savedNetwork("sink.fluidsource", 2));
  writeFileAtomic(copied, readFileBytes(card.parent_path() / "sink.fluidsource.pt"));
  try {
    AffordanceModel::load(card);
    ADD_FAILURE() << "replaced member weights loaded";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr(card.string()));
    EXPECT_THAT(e.what(), HasSubstr("sha256"));
  }
  fs::remove(copied);
  EXPECT_THROW(AffordanceModel::load(card), FileError);

  // A member without a sha256 in the card is refused by the card check itself.
  nlohmann::json j = readJsonFile(card);
  j["weights"]["ensemble"][0].erase("sha256");
  writeFileAtomic(card, j.dump(2));
  try {
    readModelCard(card);
    ADD_FAILURE() << "a member without sha256 was read";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr(card.string()));
    EXPECT_THAT(e.what(), HasSubstr("ensemble"));
  }
}

TEST(ModelEnsemble, TrainingDoesNotSaveAnEnsemble) {
  const fs::path card = savedNetwork("sink.togglebutton", 1);
  const std::vector<float> single = AffordanceModel::load(card).predictDistances(smallGrid());
  addEnsembleMember(card, savedNetwork("sink.togglebutton", 2));
  AffordanceModel ensemble = AffordanceModel::load(card);
  EXPECT_NE(ensemble.predictDistances(smallGrid()), single);
  EXPECT_THROW(ensemble.save(test::freshTempDir("out") / "sink.togglebutton.json"), ModelError);
  // A card replaced by a fresh one (what `train --init` does) predicts with one network again.
  ensemble.card().ensemble.clear();
  EXPECT_EQ(ensemble.networkCount(), 1u);
  EXPECT_EQ(ensemble.predictDistances(smallGrid()), single);
}

// What keepInitNetworks writes: the init's networks (its members but an earlier fine-tune) and
// the fine-tuned one, under the init's card.
TEST(ModelEnsemble, AFineTuneKeptBesideItsInitReplacesTheEarlierFineTune) {
  const fs::path init = savedNetwork("stove.togglebutton", 1);
  addEnsembleMember(init, savedNetwork("stove.togglebutton", 2));  // trained apart: stays
  ModelCard initCard = readModelCard(init);
  initCard.extraction.maxDistance = 0.123f;  // a calibration of the init's own
  writeModelCard(init, initCard);
  const FeatureGrid grid = smallGrid();
  const std::vector<float> initField = AffordanceModel::load(init).predictDistances(grid);
  const fs::path tuned = savedNetwork("stove.togglebutton", 3);
  const std::vector<float> tunedField = AffordanceModel::load(tuned).predictDistances(grid);

  const fs::path out = test::freshTempDir("kept") / "models";
  const fs::path card = keepInitNetworks(init, tuned, out);
  EXPECT_EQ(card, out / "stove.togglebutton.json");
  const ModelCard first = readModelCard(card);
  EXPECT_EQ(first.weightsSha256, initCard.weightsSha256);
  EXPECT_FLOAT_EQ(first.extraction.maxDistance, 0.123f);
  ASSERT_EQ(first.ensemble.size(), 2u);
  EXPECT_EQ(first.ensemble[1].sha256, readModelCard(tuned).weightsSha256);
  EXPECT_EQ(first.training["ensemble"][1]["role"], kFineTuneRole);
  EXPECT_FALSE(first.training["ensemble"][0].contains("role"));
  // Three networks, equally weighted: two thirds the init's mean field, a third the fine-tune's.
  const std::vector<float> mean = AffordanceModel::load(card).predictDistances(grid);
  for (std::size_t i = 0; i < mean.size(); ++i)
    EXPECT_NEAR(mean[i], (2.0f * initField[i] + tunedField[i]) / 3.0f, 1e-5f);

  // The next fine-tune from this model, in its own folder: the earlier fine-tune goes, file too.
  const fs::path again = savedNetwork("stove.togglebutton", 4);
  keepInitNetworks(card, again, out);
  const ModelCard second = readModelCard(card);
  ASSERT_EQ(second.ensemble.size(), 2u);
  EXPECT_EQ(second.ensemble[0].sha256, first.ensemble[0].sha256);
  EXPECT_EQ(second.ensemble[1].sha256, readModelCard(again).weightsSha256);
  EXPECT_EQ(second.training["ensemble"].size(), 2u);
  EXPECT_FALSE(fs::exists(out / "stove.togglebutton.member3.pt"));
  EXPECT_EQ(AffordanceModel::load(card).networkCount(), 3u);
}

TEST(ModelEnsemble, AFineTuneOfAnotherModelOrNoneAtAllLeavesTheFolderAlone) {
  const fs::path init = savedNetwork("sink.togglebutton", 1);
  const fs::path out = test::freshTempDir("refused") / "models";
  try {
    keepInitNetworks(init, savedNetwork("sink.fluidsource", 2), out);
    ADD_FAILURE() << "another model's network was kept";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), HasSubstr("sink.fluidsource"));
  }
  // Weights that are the init's own: nothing was fine-tuned.
  const fs::path same = test::freshTempDir("same") / "sink.togglebutton.json";
  fs::copy_file(init, same);
  fs::copy_file(init.parent_path() / "sink.togglebutton.pt", same.parent_path() / "sink.togglebutton.pt");
  try {
    keepInitNetworks(init, same, out);
    ADD_FAILURE() << "the init's own weights were added as a fine-tune";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), HasSubstr("nothing was fine-tuned"));
  }
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace sagrid::model
