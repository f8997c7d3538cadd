#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <random>
#include <thread>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/features/feature_grid.h"
#include "core/model/affordance_model.h"
#include "core/training/trainer.h"
#include "support/test_paths.h"

namespace sagrid::model {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr int kRes = 16;

// A plate of voxels with a bump-marked spot: feature 0 is 1 within two voxels of the spot, the
// descriptor is random; the target is the spot.
FeatureGrid plateFeatures(int spotI, int spotJ, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(-0.1f, 0.1f);
  FeatureGrid f;
  f.backend = "synthetic";
  f.configHash = "abc";
  f.resolution = kRes;
  f.channels = 3;
  for (int i = 2; i < 14; ++i)
    for (int j = 2; j < 14; ++j) {
      f.voxels.push_back({i, j, 5});
      const bool spot = std::abs(i - spotI) <= 1 && std::abs(j - spotJ) <= 1;
      f.values.insert(f.values.end(), {spot ? 1.0f : 0.0f, noise(rng), 0.5f});
    }
  for (int d = 0; d < 4; ++d) f.descriptor.push_back(noise(rng));
  return f;
}

TrainingSample plateSample(int i, int j, unsigned seed) {
  FeatureGrid f = plateFeatures(i, j, seed);
  return makeTrainingSample("plate" + std::to_string(seed), f, {voxelCenter({i, j, 5}, kRes)});
}

ModelCard smallCard() {
  ModelCard card;
  card.name = "stove.heatsource";
  card.category = "stove";
  card.type = "heatsource";
  card.architecture = "[3,1,8],[3,2,8,2]";
  card.featureBackend = "synthetic";
  card.featureConfigHash = "abc";
  card.featureChannels = 3;
  card.descriptorSize = 4;
  card.gridResolution = kRes;
  return card;
}

TEST(Training, LossDecreasesOnATinySet) {
  const std::vector<TrainingSample> samples = {plateSample(4, 4, 1), plateSample(10, 6, 2),
                                               plateSample(7, 11, 3), plateSample(11, 11, 4)};
  AffordanceModel model(smallCard(), 1);
  const double before = evaluateLoss(model, samples);
  TrainingOptions options;
  options.epochs = 25;
  options.batchSize = 2;
  options.learningRate = 1e-2;
  std::size_t progressCalls = 0;
  options.onProgress = [&](const TrainingProgress& p) {
    ++progressCalls;
    EXPECT_EQ(p.steps, 50u);
  };
  const auto curve = trainModel(model, samples, options);
  ASSERT_EQ(curve.size(), 25u);
  EXPECT_EQ(progressCalls, 50u);
  const double after = evaluateLoss(model, samples);
  EXPECT_LT(after, 0.5 * before) << "before " << before << " after " << after;
  EXPECT_LT(curve.back().loss, curve.front().loss);
  // The argmin of the trained field lands at the marked spot.
  const auto d = model.predictDistances(plateFeatures(4, 4, 1));
  const auto best = std::min_element(d.begin(), d.end()) - d.begin();
  const VoxelIndex v = plateFeatures(4, 4, 1).voxels[best];
  EXPECT_LE(std::abs(v.i - 4) + std::abs(v.j - 4), 2);
}

TEST(Training, RejectsEmptySetsAndSamplesWithoutTargets) {
  AffordanceModel model(smallCard(), 1);
  EXPECT_THROW(trainModel(model, {}, {}), InvalidArgument);
  auto sample = plateSample(4, 4, 1);
  sample.targets.clear();
  EXPECT_THROW(trainModel(model, {sample}, {}), InvalidArgument);
}

TEST(Training, ATimeBudgetIsPlannedFromTheTimeLeftAtTheCurrentPace) {
  EXPECT_EQ(plannedSteps(1, 2, 2, 60), 30u);    // after the first step: 29 more fit
  EXPECT_EQ(plannedSteps(10, 20, 2, 60), 30u);  // on pace
  EXPECT_EQ(plannedSteps(10, 40, 4, 60), 15u);  // the steps got twice as slow: five more fit
  EXPECT_EQ(plannedSteps(10, 58, 4, 60), 10u);  // none more fits: stop here
  EXPECT_EQ(plannedSteps(10, 20, 1, 60), 50u);  // the machine got idle: forty more
  EXPECT_EQ(plannedSteps(12, 70, 2, 60), 12u);  // over budget: never fewer than done
  EXPECT_EQ(plannedSteps(0, 0, 100, 60), 1u);   // at least one step
  EXPECT_EQ(plannedSteps(3, 1, 0, 60), 3u);     // no pace yet
}

TEST(Training, AMachineThatGetsBusyShortensATimedRun) {
  const std::vector<TrainingSample> samples = {plateSample(4, 4, 1), plateSample(10, 6, 2)};
  TrainingOptions options;
  options.minutes = 2.0 / 60.0;
  options.batchSize = 1;  // two steps per epoch
  options.augmentation.warpVoxels = 0;
  // Epoch 1 runs at full speed (a plan of many steps); from epoch 2 on every step is slowed by
  // 0.2 s, as by a GUI drawing beside the run: the plan must shrink to what still fits.
  std::size_t lastPlan = 0;
  options.onProgress = [&](const TrainingProgress& p) {
    lastPlan = p.steps;
    if (p.epoch >= 2) std::this_thread::sleep_for(std::chrono::milliseconds(200));
  };
  AffordanceModel model(smallCard(), 1);
  const auto curve = trainModel(model, samples, options);
  EXPECT_GE(curve.size(), 2u);
  EXPECT_LE(curve.size(), 8u);  // 2 s at 0.4 s an epoch, not the count epoch 1 planned
  EXPECT_LE(lastPlan, 16u);
  // A budget can end part way through an epoch: the run still ends with a complete record.
  EXPECT_GT(curve.back().loss, 0.0);
}

TEST(Training, ResumeContinuesToTheSameResultAsOneRun) {
  const std::vector<TrainingSample> samples = {plateSample(4, 4, 1), plateSample(10, 6, 2)};
  const fs::path dir = test::freshTempDir();
  TrainingOptions options;
  options.epochs = 4;
  options.augmentation.warpVoxels = 0;
  options.checkpointFile = dir / "a.checkpoint";
  AffordanceModel straight(smallCard(), 1);
  trainModel(straight, samples, options);

  // Interrupted after two epochs (cancel), then resumed.
  AffordanceModel first(smallCard(), 1);
  options.checkpointFile = dir / "b.checkpoint";
  std::atomic<bool> cancel{false};
  options.cancel = &cancel;
  options.onProgress = [&](const TrainingProgress& p) {
    if (p.step == 2) cancel = true;  // one step per epoch: stop during epoch 3
  };
  options.batchSize = 2;
  EXPECT_THROW(trainModel(first, samples, options), Cancelled);
  options.cancel = nullptr;
  options.onProgress = nullptr;
  options.resume = true;
  AffordanceModel resumed(smallCard(), 99);  // weights come from the checkpoint
  const auto curve = trainModel(resumed, samples, options);
  ASSERT_EQ(curve.size(), 4u);

  AffordanceModel straight2(smallCard(), 1);
  options.resume = false;
  options.checkpointFile = dir / "c.checkpoint";
  trainModel(straight2, samples, options);
  const auto expected = straight2.predictDistances(plateFeatures(4, 4, 1));
  const auto got = resumed.predictDistances(plateFeatures(4, 4, 1));
  ASSERT_EQ(expected.size(), got.size());
  for (std::size_t v = 0; v < got.size(); ++v) EXPECT_NEAR(got[v], expected[v], 1e-4f);
}

TEST(ModelFiles, SaveLoadRoundTripGivesIdenticalOutputs) {
  const fs::path dir = test::freshTempDir();
  AffordanceModel model(smallCard(), 7);
  trainModel(model, {plateSample(4, 4, 1)}, [] {
    TrainingOptions o;
    o.epochs = 2;
    return o;
  }());
  model.save(dir / "stove.heatsource.json");
  ASSERT_TRUE(fs::exists(dir / "stove.heatsource.pt"));
  const AffordanceModel loaded = AffordanceModel::load(dir / "stove.heatsource.json");
  EXPECT_EQ(loaded.card().weightsSha256.size(), 64u);
  EXPECT_EQ(loaded.card().architecture, "[3,1,8],[3,2,8,2]");
  const auto features = plateFeatures(9, 9, 5);
  EXPECT_EQ(model.predictDistances(features), loaded.predictDistances(features));
}

TEST(ModelFiles, TruncatedOrReplacedWeightsGiveAClearError) {
  const fs::path dir = test::freshTempDir();
  AffordanceModel model(smallCard(), 7);
  model.save(dir / "m.json");
  const std::string bytes = readFileBytes(dir / "m.pt");
  writeFileAtomic(dir / "m.pt", bytes.substr(0, bytes.size() / 2));
  try {
    AffordanceModel::load(dir / "m.json");
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("m.pt"));
    EXPECT_THAT(e.what(), HasSubstr("sha256 differs"));
  }
  // Without a recorded sha256, the archive reader itself must catch the truncation.
  auto card = readModelCard(dir / "m.json");
  card.weightsSha256.clear();
  writeModelCard(dir / "m.json", card);
  try {
    AffordanceModel::load(dir / "m.json");
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("truncated"));
  }
}

TEST(ModelFiles, WeightsOfAnotherArchitectureAreRejected) {
  const fs::path dir = test::freshTempDir();
  AffordanceModel model(smallCard(), 7);
  model.save(dir / "m.json");
  auto card = readModelCard(dir / "m.json");
  card.architecture = "[3,1,8],[3,2,4,2]";
  card.weightsSha256.clear();
  writeModelCard(dir / "m.json", card);
  try {
    AffordanceModel::load(dir / "m.json");
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), HasSubstr("shape"));
  }
}

TEST(ModelFiles, FeatureMismatchIsAModelError) {
  AffordanceModel model(smallCard(), 7);
  auto f = plateFeatures(4, 4, 1);
  f.backend = "embedded";
  EXPECT_THROW(model.predictDistances(f), ModelError);
  f = plateFeatures(4, 4, 1);
  f.configHash = "other";
  try {
    model.predictDistances(f);
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), HasSubstr("feature config"));
  }
  f = plateFeatures(4, 4, 1);
  f.resolution = 32;
  EXPECT_THROW(model.predictDistances(f), ModelError);
  f = plateFeatures(4, 4, 1);
  f.descriptor.pop_back();
  EXPECT_THROW(model.predictDistances(f), ModelError);
}

TEST(ModelFiles, CardRejectsUnknownSchemaAndMissingFields) {
  const fs::path dir = test::freshTempDir();
  writeFileAtomic(dir / "a.json", R"({"schema": "sagrid.model/9"})");
  EXPECT_THROW(readModelCard(dir / "a.json"), FileError);
  writeFileAtomic(dir / "b.json", R"({"schema": "sagrid.model/1", "name": "x.y"})");
  try {
    readModelCard(dir / "b.json");
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("missing field"));
  }
  EXPECT_THROW(splitModelName("stove"), InvalidArgument);
  EXPECT_EQ(splitModelName("sink.fluidsource").second, "fluidsource");
}

}  // namespace
}  // namespace sagrid::model
