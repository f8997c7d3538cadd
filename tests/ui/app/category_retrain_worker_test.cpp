// The Train panel's "Retrain category classifier" (issue 40): the categories curated in the GUI's
// training set retrain the classifier of the loaded models, on its own training folders that are
// still here plus the training set, guarded on held-out curated objects; the loaded classifier is
// never overwritten, the verdict shows in the panel and goes to guard.jsonl.
#include <gtest/gtest.h>

#include <fstream>

#include "core/annotate/category_classifier.h"
#include "core/annotate/category_update.h"
#include "core/annotate/model_set.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/generate/dataset_generator.h"
#include "core/annotate/annotate.h"
#include "core/dataset/dataset.h"
#include "core/labels/labels.h"
#include "support/test_paths.h"
#include "ui/app/training_worker.h"
#include "training_worker_support.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

TrainingStatus retrain(const fs::path& dir, const fs::path& heldOut,
                       std::vector<QueueEntry> requeue = {}) {
  TrainingRequest request = test::requestIn(dir);
  request.requeue = std::move(requeue);
  request.heldOut = heldOut;
  request.categoryClassifier = true;
  return test::runToEnd(std::move(request), 300);
}

// Generated stand-ins: the classifier's own training folder, the curator's training set, and
// held-out curated objects, in `dir`.
void generateFolders(const fs::path& dir) {
  gen::generateDataset({{"stove", 2, 51}, {"sink", 2, 52}, {"none", 2, 53}}, gen::MeshFormat::Obj,
                       dir / "own");
  gen::generateDataset({{"stove", 2, 54}, {"sink", 1, 55}, {"none", 1, 56}}, gen::MeshFormat::Obj,
                       dir / "curated");
  gen::generateDataset({{"stove", 2, 57}, {"sink", 2, 58}, {"none", 2, 59}}, gen::MeshFormat::Obj,
                       dir / "held-out");
}

// The loaded models: the shipped ones, their classifier `loaded` saved with a training record of
// "own" (weight 2), a folder this machine lacks, and `iterations` gradient steps.
CategoryClassifier saveLoaded(const fs::path& dir, CategoryClassifier loaded, int iterations) {
  loaded.training["data"] = {(dir / "own").string() + "@2", (dir / "gone").string()};
  loaded.training["iterations"] = iterations;
  loaded.save(dir / "loaded" / kCategoryClassifierFile);
  return loaded;
}

const fs::path kShipped = fs::path(SAGRID_SOURCE_DIR) / "resources" / "models";

// A classifier retrained for one gradient step decides the held-out objects worse than the
// shipped one: refused, written to refused/, the loaded one untouched.
TEST(CategoryRetrainWorker, AWorseRetrainingIsRefusedAndTheLoadedClassifierStays) {
  const fs::path dir = test::freshTempDir();
  generateFolders(dir);
  fs::copy(kShipped, dir / "loaded", fs::copy_options::recursive);
  // A softmax classifier: its gradient steps make the retraining worse (the shipped one is trees).
  CategoryClassifier softmax = CategoryClassifier::load(kShipped / kCategoryClassifierFile);
  softmax.training.erase("trees");
  const CategoryClassifier loaded = saveLoaded(dir, softmax, 1);
  const std::string before = readFileBytes(dir / "loaded" / kCategoryClassifierFile);

  const TrainingStatus status = retrain(dir, dir / "held-out");
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 1u);
  EXPECT_NE(status.verdicts[0].find("refused, current classifier kept"), std::string::npos)
      << status.verdicts[0];
  EXPECT_NE(status.finished.find("1 of its training folders are not on this machine"), std::string::npos)
      << status.finished;
  EXPECT_EQ(readFileBytes(dir / "loaded" / kCategoryClassifierFile), before);
  // The folder the GUI predicts from afterwards holds the loaded classifier, not the refused one.
  EXPECT_EQ(readFileBytes(dir / "out" / kCategoryClassifierFile), before);
  EXPECT_NO_THROW(ModelSet::load(dir / "out"));
  const CategoryClassifier candidate =
      CategoryClassifier::load(dir / "out" / "refused" / kCategoryClassifierFile);
  // Trained on what is here of its own data, then the curated set weighted as real objects.
  const std::vector<std::string> data = candidate.training.at("data");
  ASSERT_EQ(data.size(), 2u);
  EXPECT_EQ(data[0], (dir / "own").string() + "@2");
  EXPECT_EQ(data[1], (dir / "curated").string() + "@3");
  EXPECT_EQ(candidate.training.at("missing_data").at(0), (dir / "gone").string());
  EXPECT_EQ(candidate.training.at("objects").at("stove"), 4);  // 2 own + 2 curated
  EXPECT_EQ(candidate.inputSet().topRelief, loaded.inputSet().topRelief);
  EXPECT_EQ(candidate.inputSet().partStatistics, loaded.inputSet().partStatistics);
  EXPECT_DOUBLE_EQ(candidate.threshold(), loaded.threshold());
  EXPECT_EQ(candidate.evidence.thresholds, loaded.evidence.thresholds);

  std::ifstream log(dir / "out" / "guard.jsonl");
  std::string line;
  ASSERT_TRUE(std::getline(log, line));
  EXPECT_NE(line.find("\"model\":\"category\""), std::string::npos) << line;
  EXPECT_NE(line.find("\"adopted\":false"), std::string::npos) << line;
}

// The review queue: an unreviewed object labelled sink by the classifier before, and one the
// curator accepted; their labels files.
std::vector<QueueEntry> queueOf(const fs::path& dir) {
  return test::reviewQueue(dir, readDataset(dir / "held-out").front().mesh, "sink");
}

// Loaded with a classifier of one gradient step, the curated retraining (2,000 steps) decides the
// held-out objects better: adopted into the models folder written to, and the unreviewed objects
// of the queue are predicted again by it (the reviewed ones stay as the curator left them).
TEST(CategoryRetrainWorker, ABetterRetrainingIsAdopted) {
  const fs::path dir = test::freshTempDir();
  generateFolders(dir);
  fs::copy(kShipped, dir / "loaded", fs::copy_options::recursive);
  const CategoryClassifier shipped = CategoryClassifier::load(kShipped / kCategoryClassifierFile);
  const auto features = ModelSet::load(kShipped).featureOptions();
  std::vector<std::string> missing;
  // A classifier of boosted trees (the shipped one) retrains as trees, with its rounds and depth.
  ASSERT_TRUE(shipped.training.contains("trees"));
  CategoryClassifier trees = shipped;
  trees.training["data"] = {(dir / "own").string()};
  EXPECT_EQ(retrainCategoryClassifier(trees, dir / "curated", kCuratedCategoryWeight, features, missing)
                .training.at("trees"),
            shipped.training.at("trees"));
  // Trees grown on shares of the objects and inputs retrain with the same shares and seed.
  trees.training["trees"]["row_share"] = 0.5;
  trees.training["trees"]["feature_share"] = 0.25;
  trees.training["trees"]["seed"] = 7;
  EXPECT_EQ(retrainCategoryClassifier(trees, dir / "curated", kCuratedCategoryWeight, features, missing)
                .training.at("trees"),
            trees.training.at("trees"));
  // A softmax classifier of one gradient step.
  CategoryClassifier oneStep = shipped;
  oneStep.training.erase("trees");
  oneStep.training["data"] = {(dir / "own").string()};
  oneStep.training["iterations"] = 1;
  oneStep = retrainCategoryClassifier(oneStep, dir / "curated", kCuratedCategoryWeight, features,
                                      missing);
  saveLoaded(dir, oneStep, 2000);
  const std::string before = readFileBytes(dir / "loaded" / kCategoryClassifierFile);
  const auto queue = queueOf(dir);
  ASSERT_TRUE(fs::exists(queue[0].mesh)) << queue[0].mesh;
  const std::string accepted = readFileBytes(queue[1].labels);

  const TrainingStatus status = retrain(dir, dir / "held-out", queue);
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 1u);
  EXPECT_NE(status.verdicts[0].find(": adopted"), std::string::npos) << status.verdicts[0];
  EXPECT_NE(status.finished.find("1 unreviewed object(s) predicted again"), std::string::npos)
      << status.finished;
  const ObjectLabels again = readLabels(queue[0].labels);
  const ModelSet adopted = ModelSet::load(dir / "out");
  AnnotateOptions decide;
  decide.features = adopted.featureOptions();
  EXPECT_EQ(again.object.category,
            annotateMeshFile(queue[0].mesh, "check", adopted, decide, dir / "check").labels.object.category);
  EXPECT_EQ(readFileBytes(queue[1].labels), accepted);
  EXPECT_EQ(readFileBytes(dir / "loaded" / kCategoryClassifierFile), before);
  ASSERT_TRUE(fs::exists(dir / "out" / kCategoryClassifierFile));
  EXPECT_FALSE(fs::exists(dir / "out" / "refused"));
  EXPECT_EQ(CategoryClassifier::load(dir / "out" / kCategoryClassifierFile).training.at("iterations"), 2000);
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
