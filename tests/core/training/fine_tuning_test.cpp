// Fine-tuning through trainFromDataset: --init weights, mixed datasets, the card's record of both,
// mismatches, resume over init. Tiny generated datasets on a 16^3 grid with few views.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <optional>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/dataset/dataset.h"
#include "core/features/feature_pipeline.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "core/model/affordance_model.h"
#include "core/training/dataset_training.h"
#include "support/test_paths.h"
#include "support/tiny_training.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr const char* kModel = "stove.heatsource";
constexpr const char* kArch = test::kTinyArchitecture;
using test::tinyFeatures;

// Without augmentation: the first step's batch is the object as it is.
DatasetTrainingOptions tinyOptions(const fs::path& out) {
  DatasetTrainingOptions o = test::tinyTraining(kModel, {}, out);
  o.training.augmentation.rotate = false;
  o.training.augmentation.reflect = false;
  o.training.augmentation.translate = false;
  o.training.augmentation.warpVoxels = 0;
  return o;
}

class FineTuning : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    s_dir = new fs::path(test::freshTempDir("fine_tuning_suite"));
    gen::generateDataset({{"stove", 1, 5}}, gen::MeshFormat::Obj, *s_dir / "one");
    gen::generateDataset({{"stove", 2, 6}}, gen::MeshFormat::Obj, *s_dir / "two");
    gen::generateDataset({{"sink", 1, 7}}, gen::MeshFormat::Obj, *s_dir / "sinks");
    DatasetTrainingOptions base = tinyOptions(*s_dir / "base");
    base.dataDir = *s_dir / "two";
    base.training.epochs = 2;
    trainFromDataset(base);
  }
  static void TearDownTestSuite() {
    delete s_dir;
    s_dir = nullptr;
  }
  static fs::path dir() { return *s_dir; }
  static fs::path baseCard() { return *s_dir / "base" / (std::string(kModel) + ".json"); }
  static fs::path* s_dir;
};
fs::path* FineTuning::s_dir = nullptr;

TEST_F(FineTuning, FirstStepLossIsTheInitModelsLossOnThatBatch) {
  const fs::path out = test::freshTempDir();
  DatasetTrainingOptions o = tinyOptions(out / "tuned");
  o.dataDir = dir() / "one";  // one object: the first batch is that object
  o.init = dir() / "base";    // a folder: <dir>/<model>.json
  double firstLoss = -1;
  o.training.onProgress = [&](const model::TrainingProgress& p) {
    if (p.step == 1) firstLoss = p.loss;
  };
  trainFromDataset(o);

  const DatasetEntry entry = readDataset(dir() / "one").front();
  FeatureOptions features = tinyFeatures();
  features.cacheDir = dir() / "one" / ".sagrid-cache";
  const FeatureGrid grid = extractFeatures(entry.mesh, features);
  const TrainingSample sample = makeTrainingSample(
      entry.id, grid, normalizedTargets(readLabels(entry.labels), "heatsource", grid));
  model::AffordanceModel init = model::AffordanceModel::load(baseCard());
  const double initLoss = model::evaluateLoss(init, {sample}, 0, true);
  EXPECT_NEAR(firstLoss, initLoss, 1e-5);
  // Fresh weights give another loss, so the equality above says the weights came from --init.
  model::AffordanceModel fresh(init.card(), 1);
  EXPECT_GT(std::abs(model::evaluateLoss(fresh, {sample}, 0, true) - initLoss), 1e-3);
}

TEST_F(FineTuning, ThePerModelSwitchesAreKeptFromTheInitCardUnlessGiven) {
  // The second pass and the crease patches' candidates: choices about the model, not fitted.
  struct Switch {
    const char* name;
    bool ExtractionSettings::*inCard;
    std::optional<bool> DatasetTrainingOptions::*given;
  };
  for (const Switch& s : {Switch{"coarse_to_fine", &ExtractionSettings::coarseToFine,
                                 &DatasetTrainingOptions::coarseToFine},
                          Switch{"crease_patches", &ExtractionSettings::creasePatches,
                                 &DatasetTrainingOptions::creasePatches}}) {
    SCOPED_TRACE(s.name);
    const fs::path out = test::freshTempDir();
    const auto trained = [&](const DatasetTrainingOptions& o) {
      return model::readModelCard(trainFromDataset(o).cardFile).extraction.*s.inCard;
    };
    // The base model with the switch on in its card.
    fs::copy(dir() / "base", out / "init");
    const fs::path initCard = out / "init" / (std::string(kModel) + ".json");
    model::ModelCard card = model::readModelCard(initCard);
    card.extraction.*s.inCard = true;
    model::writeModelCard(initCard, card);

    DatasetTrainingOptions o = tinyOptions(out / "kept");
    o.dataDir = dir() / "one";
    o.init = out / "init";
    EXPECT_TRUE(trained(o));
    o.outDir = out / "off";
    o.*s.given = false;
    EXPECT_FALSE(trained(o));
    o = tinyOptions(out / "scratch");
    o.dataDir = dir() / "one";
    EXPECT_FALSE(trained(o));
    o.outDir = out / "scratch-on";
    o.*s.given = true;
    EXPECT_TRUE(trained(o));
  }
}

TEST_F(FineTuning, CardRecordsEveryDatasetAndTheInitModel) {
  const fs::path out = test::freshTempDir();
  DatasetTrainingOptions o = tinyOptions(out);
  o.architecture.clear();  // taken from the init card
  o.datasets = {{dir() / "one", 3.0, "data", {}}, {dir() / "two", 1.0, "replay", {}}};
  o.init = baseCard().parent_path() / (std::string(kModel) + ".pt");  // MODEL.pt form
  const auto result = trainFromDataset(o);
  EXPECT_EQ(result.objectsUsed, 3u);
  const model::ModelCard card = model::readModelCard(result.cardFile);
  EXPECT_EQ(card.architecture, model::readModelCard(baseCard()).architecture);
  const auto& datasets = card.training.at("datasets");
  ASSERT_EQ(datasets.size(), 2u);
  EXPECT_EQ(datasets[0].at("role"), "data");
  EXPECT_EQ(datasets[0].at("weight"), 3.0);
  EXPECT_EQ(datasets[0].at("objects"), 1);
  EXPECT_EQ(datasets[0].at("sha256_of"), "manifest.jsonl");
  EXPECT_EQ(datasets[0].at("sha256").get<std::string>().size(), 64u);
  EXPECT_EQ(datasets[1].at("role"), "replay");
  EXPECT_EQ(datasets[1].at("objects"), 2);
  EXPECT_NE(datasets[0].at("sha256"), datasets[1].at("sha256"));
  const auto& init = card.training.at("init");
  EXPECT_EQ(init.at("weights_sha256"), model::readModelCard(baseCard()).weightsSha256);
  EXPECT_EQ(init.at("card_sha256").get<std::string>().size(), 64u);
  EXPECT_THAT(init.at("path").get<std::string>(), HasSubstr("base"));
  // 3 training objects < kMinCalibrationObjects: the init's calibration is kept.
  EXPECT_FALSE(result.recalibrated);
  EXPECT_EQ(card.extraction.maxDistance, model::readModelCard(baseCard()).extraction.maxDistance);
  EXPECT_EQ(card.extraction.nmsRadius, model::readModelCard(baseCard()).extraction.nmsRadius);
}

TEST_F(FineTuning, MismatchedArchitectureOrBackendIsAModelErrorNamingBoth) {
  const fs::path out = test::freshTempDir();
  DatasetTrainingOptions o = tinyOptions(out / "a");
  o.dataDir = dir() / "one";
  o.init = dir() / "base";
  o.architecture = "[3,1,8]";
  try {
    trainFromDataset(o);
    FAIL() << "expected ModelError";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), HasSubstr("architecture"));
    EXPECT_THAT(e.what(), HasSubstr("[3,1,8],[3,2,8,2]"));  // init's
    EXPECT_THAT(e.what(), HasSubstr("has [3,1,8],"));      // requested (then the message goes on)
  }
  // An init card for another backend (edited copy of the base model).
  fs::create_directories(out / "other");
  for (const char* ext : {".pt", ".json"})
    fs::copy_file(dir() / "base" / (std::string(kModel) + ext),
                  out / "other" / (std::string(kModel) + ext));
  model::ModelCard other = model::readModelCard(out / "other" / (std::string(kModel) + ".json"));
  other.featureBackend = "dinov2";
  model::writeModelCard(out / "other" / (std::string(kModel) + ".json"), other);
  o.architecture = kArch;
  o.init = out / "other";
  try {
    trainFromDataset(o);
    FAIL() << "expected ModelError";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), HasSubstr("feature backend"));
    EXPECT_THAT(e.what(), HasSubstr("dinov2"));
    EXPECT_THAT(e.what(), HasSubstr("embedded"));
  }
  o.init = out / "missing";
  EXPECT_THROW(trainFromDataset(o), FileError);
}

TEST_F(FineTuning, ADatasetWithoutTheCategoryIsAnErrorNamingDatasetAndModel) {
  DatasetTrainingOptions o = tinyOptions(test::freshTempDir());
  o.datasets = {{dir() / "one", 1.0, "data", {}}, {dir() / "sinks", 1.0, "data", {}}};
  try {
    trainFromDataset(o);
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(e.what(), HasSubstr((dir() / "sinks").string()));
    EXPECT_THAT(e.what(), HasSubstr(kModel));
  }
}

TEST_F(FineTuning, ResumeWinsOverInitAndEndsWhereAnUninterruptedRunEnds) {
  const fs::path out = test::freshTempDir();
  DatasetTrainingOptions o = tinyOptions(out / "straight");
  o.dataDir = dir() / "two";
  o.init = dir() / "base";
  o.training.epochs = 2;
  trainFromDataset(o);

  o.outDir = out / "interrupted";
  std::atomic<bool> cancel{false};
  o.training.cancel = &cancel;
  o.training.onProgress = [&](const model::TrainingProgress& p) {
    if (p.step == 3) cancel = true;  // two steps per epoch: stop in epoch 2
  };
  EXPECT_THROW(trainFromDataset(o), Cancelled);
  EXPECT_TRUE(fs::exists(out / "interrupted" / (std::string(kModel) + ".checkpoint")));
  o.training.cancel = nullptr;
  o.training.onProgress = nullptr;
  o.training.resume = true;
  // Resume with an init of other weights: were the init used, the result would differ.
  DatasetTrainingOptions other = tinyOptions(out / "other");
  other.dataDir = dir() / "one";
  other.training.seed = 9;
  trainFromDataset(other);
  o.init = out / "other";
  const auto resumed = trainFromDataset(o);
  ASSERT_EQ(resumed.curve.size(), 2u);

  model::AffordanceModel a =
      model::AffordanceModel::load(out / "straight" / (std::string(kModel) + ".json"));
  model::AffordanceModel b = model::AffordanceModel::load(resumed.cardFile);
  const DatasetEntry entry = readDataset(dir() / "two").front();
  FeatureOptions features = tinyFeatures();
  features.cacheDir = dir() / "two" / ".sagrid-cache";
  const FeatureGrid grid = extractFeatures(entry.mesh, features);
  const auto expected = a.predictDistances(grid);
  const auto got = b.predictDistances(grid);
  ASSERT_EQ(expected.size(), got.size());
  for (std::size_t v = 0; v < got.size(); ++v) EXPECT_NEAR(got[v], expected[v], 1e-4f);
}

}  // namespace
}  // namespace sagrid
