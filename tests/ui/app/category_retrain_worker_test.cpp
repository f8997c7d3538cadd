// The Train panel's "Retrain category classifier" (issue 40): the categories curated in the GUI's
// training set retrain the classifier of the loaded models, on its own training folders that are
// still here plus the training set, guarded on held-out curated objects; the loaded classifier is
// never overwritten, the verdict shows in the panel and goes to guard.jsonl.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "core/annotate/category_classifier.h"
#include "core/annotate/category_update.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/generate/dataset_generator.h"
#include "support/test_paths.h"
#include "ui/app/training_worker.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

TrainingStatus retrain(const fs::path& dir, const fs::path& heldOut) {
  TrainingWorker worker;
  TrainingRequest request;
  request.dataset = dir / "curated";
  request.outDir = dir / "out";
  request.initDir = dir / "loaded";
  request.heldOut = heldOut;
  request.categoryClassifier = true;
  worker.start(request);
  for (int i = 0; i < 20 * 300 && worker.running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(worker.running()) << "retraining did not finish in 300 s";
  EXPECT_EQ(worker.takeFinished(), worker.status().error.empty());
  return worker.status();
}

TEST(CategoryRetrainWorker, RetrainsOnItsOwnDataAndTheCuratedSetGuardedOnHeldOutObjects) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 51}, {"sink", 2, 52}, {"none", 2, 53}}, gen::MeshFormat::Obj,
                       dir / "own");
  gen::generateDataset({{"stove", 2, 54}, {"sink", 1, 55}, {"none", 1, 56}}, gen::MeshFormat::Obj,
                       dir / "curated");
  gen::generateDataset({{"stove", 2, 57}, {"sink", 2, 58}, {"none", 2, 59}}, gen::MeshFormat::Obj,
                       dir / "held-out");
  // The loaded models: the shipped ones, their classifier trained on "own" (weight 2) and on a
  // folder this machine lacks.
  fs::copy(fs::path(SAGRID_SOURCE_DIR) / "resources" / "models", dir / "loaded",
           fs::copy_options::recursive);
  const fs::path loadedFile = dir / "loaded" / kCategoryClassifierFile;
  CategoryClassifier loaded = CategoryClassifier::load(loadedFile);
  loaded.training["data"] = {(dir / "own").string() + "@2", (dir / "gone").string()};
  loaded.training["iterations"] = 2000;
  loaded.save(loadedFile);
  const std::string before = readFileBytes(loadedFile);

  const TrainingStatus status = retrain(dir, dir / "held-out");
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 1u);
  const bool adopted = status.verdicts[0].find(": adopted") != std::string::npos;
  EXPECT_TRUE(adopted || status.verdicts[0].find("refused, current classifier kept") != std::string::npos)
      << status.verdicts[0];
  EXPECT_NE(status.finished.find("1 of its training folders are not on this machine"), std::string::npos)
      << status.finished;
  EXPECT_EQ(readFileBytes(loadedFile), before);  // the loaded classifier is never overwritten

  const fs::path written = adopted ? dir / "out" / kCategoryClassifierFile
                                   : dir / "out" / "refused" / kCategoryClassifierFile;
  ASSERT_TRUE(fs::exists(written));
  EXPECT_NE(fs::exists(dir / "out" / kCategoryClassifierFile), !adopted);
  const CategoryClassifier candidate = CategoryClassifier::load(written);
  // Trained on what is here of its own data, then the curated set weighted as real objects.
  const std::vector<std::string> data = candidate.training.at("data");
  ASSERT_EQ(data.size(), 2u);
  EXPECT_EQ(data[0], (dir / "own").string() + "@2");
  EXPECT_EQ(data[1], (dir / "curated").string() + "@3");
  EXPECT_EQ(candidate.training.at("missing_data").at(0), (dir / "gone").string());
  EXPECT_EQ(candidate.training.at("objects").at("stove"), 4);  // 2 own + 2 curated
  EXPECT_EQ(candidate.topRelief(), loaded.topRelief());
  EXPECT_DOUBLE_EQ(candidate.threshold(), loaded.threshold());
  EXPECT_EQ(candidate.evidence.thresholds, loaded.evidence.thresholds);

  std::ifstream log(dir / "out" / "guard.jsonl");
  std::string line;
  ASSERT_TRUE(std::getline(log, line));
  EXPECT_NE(line.find("\"model\":\"category\""), std::string::npos) << line;
}

// Held-out objects of one class cannot judge a classifier: the panel shows why; nothing written.
TEST(CategoryRetrainWorker, AOneClassHeldOutFolderIsRefusedWithItsReason) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 61}, {"none", 1, 62}}, gen::MeshFormat::Obj, dir / "curated");
  gen::generateDataset({{"sink", 2, 63}}, gen::MeshFormat::Obj, dir / "held-out");
  fs::copy(fs::path(SAGRID_SOURCE_DIR) / "resources" / "models", dir / "loaded",
           fs::copy_options::recursive);
  CategoryClassifier loaded = CategoryClassifier::load(dir / "loaded" / kCategoryClassifierFile);
  loaded.training["data"] = nlohmann::json::array();
  loaded.training["iterations"] = 200;
  loaded.save(dir / "loaded" / kCategoryClassifierFile);
  const TrainingStatus status = retrain(dir, dir / "held-out");
  EXPECT_NE(status.error.find("only sink objects"), std::string::npos) << status.error;
  EXPECT_FALSE(fs::exists(dir / "out" / kCategoryClassifierFile));
  EXPECT_FALSE(fs::exists(dir / "out" / "refused"));
}

TEST(WeightedFolder, ParsesAWeightAndNamesABadOne) {
  EXPECT_EQ(parseWeightedFolder("a/b").dir, fs::path("a/b"));
  EXPECT_DOUBLE_EQ(parseWeightedFolder("a/b").weight, 1.0);
  EXPECT_DOUBLE_EQ(parseWeightedFolder("a/b@3").weight, 3.0);
  EXPECT_EQ(parseWeightedFolder("a/b@0.5").dir, fs::path("a/b"));
  for (const char* bad : {"a@x", "a@", "a@-1", "a@2x"}) {
    try {
      parseWeightedFolder(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace sagrid::ui
