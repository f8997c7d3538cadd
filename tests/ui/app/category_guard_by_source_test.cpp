// The Train panel's "Retrain category classifier" without a held-out folder (issue 40: updates
// guarded on curated objects left out by source): the training set's objects judge the retrained
// classifier's recipe and the loaded one, each source of them left out of training in turn; a
// training set of one source retrains unguarded and says so.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/annotate/category_classifier.h"
#include "core/annotate/category_update.h"
#include "core/annotate/model_set.h"
#include "core/common/atomic_file.h"
#include "core/generate/dataset_generator.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"
#include "training_worker_support.h"
#include "ui/app/training_worker.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

const fs::path kShipped = fs::path(SAGRID_SOURCE_DIR) / "resources" / "models";

TrainingStatus retrainWithoutHeldOut(const fs::path& dir) {
  TrainingRequest request = test::requestIn(dir);
  request.categoryClassifier = true;
  return test::runToEnd(std::move(request), 300);
}

// The curator's training set dir/curated: `each` stoves, sinks and look-alikes from each of two
// repositories (a provenance record beside each mesh, as the corpora write), or all from one.
void generateCurated(const fs::path& dir, bool twoSources, int each = 1) {
  gen::generateDataset({{"stove", 2 * each, 71}, {"sink", 2 * each, 72}, {"none", 2 * each, 73}},
                       gen::MeshFormat::Obj, dir / "curated");
  if (twoSources) test::assignSources(dir / "curated", {"repo-a", "repo-b"});
}

// The loaded models: the shipped ones with `classifier` as their category.json, recording
// `data` as its training folders.
void saveLoaded(const fs::path& dir, CategoryClassifier classifier, const nlohmann::json& data) {
  fs::copy(kShipped, dir / "loaded", fs::copy_options::recursive);
  classifier.training["data"] = data;
  classifier.save(dir / "loaded" / kCategoryClassifierFile);
}

std::string lastGuardLine(const fs::path& modelsDir) {
  std::ifstream log(modelsDir / "guard.jsonl");
  std::string line, last;
  while (std::getline(log, line)) last = line;
  return last;
}

// The loaded classifier learned from a folder without sinks (it never answers "sink"); its
// recipe, trained again without each source in turn, still never does, while the recipe with the
// training set learns sinks from the other source: adopted.
TEST(CategoryGuardBySource, ARecipeThatLearnsFromTheCuratedSourcesIsAdopted) {
  const fs::path dir = test::freshTempDir();
  generateCurated(dir, true, 3);
  gen::generateDataset({{"stove", 6, 74}, {"none", 6, 75}}, gen::MeshFormat::Obj, dir / "own");
  const FeatureOptions features = ModelSet::load(kShipped).featureOptions();
  CategoryTrainingOptions options;
  options.iterations = 2000;
  options.quadratic = false;  // few objects
  CategoryClassifier noSinks = CategoryClassifier::train(
      collectWeightedSamples({{dir / "own", 1.0}}, features, {}, {}), options);
  const CategoryClassifier shipped = CategoryClassifier::load(kShipped / kCategoryClassifierFile);
  noSinks.featureBackend = shipped.featureBackend;
  noSinks.featureConfigHash = shipped.featureConfigHash;
  noSinks.gridResolution = shipped.gridResolution;
  saveLoaded(dir, noSinks, {(dir / "own").string()});

  const TrainingStatus status = retrainWithoutHeldOut(dir);
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 1u);
  const std::string& verdict = status.verdicts[0];
  EXPECT_NE(
      verdict.find("on 18 curated objects, each source of 2 left out of training in turn: adopted"),
      std::string::npos)
      << verdict;
  EXPECT_EQ(verdict.find("as it is"), std::string::npos) << verdict;
  // Each class's figures before and after: the current recipe never answers "sink".
  EXPECT_NE(verdict.find("sinks 0/6 -> "), std::string::npos) << verdict;
  EXPECT_TRUE(fs::exists(dir / "out" / kCategoryClassifierFile));
  EXPECT_FALSE(fs::exists(dir / "out" / "refused"));
  const auto line = nlohmann::json::parse(lastGuardLine(dir / "out"));
  EXPECT_EQ(line.at("judged_by_source").at(0), (dir / "curated").string());
  EXPECT_EQ(line.at("sources"), 2);
  EXPECT_TRUE(line.at("adopted").get<bool>());
  EXPECT_GT(line.at("candidate_share_right").get<double>(),
            line.at("current_share_right").get<double>());
}

// The shipped classifier, whose training folders are not on this machine, is judged as it is on
// the training set; a recipe of six objects, each source deciding the other, does no better:
// refused, the loaded classifier untouched.
TEST(CategoryGuardBySource, TheShippedClassifierIsJudgedAsItIsAndKeptAgainstAFewObjects) {
  const fs::path dir = test::freshTempDir();
  generateCurated(dir, true);
  saveLoaded(dir, CategoryClassifier::load(kShipped / kCategoryClassifierFile),
             {(dir / "gone").string()});
  const std::string before = readFileBytes(dir / "loaded" / kCategoryClassifierFile);

  const TrainingStatus status = retrainWithoutHeldOut(dir);
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 1u);
  const std::string& verdict = status.verdicts[0];
  EXPECT_NE(verdict.find("the current classifier as it is: 1 of its training folders are not here"),
            std::string::npos)
      << verdict;
  EXPECT_NE(verdict.find("refused, current classifier kept"), std::string::npos) << verdict;
  EXPECT_EQ(readFileBytes(dir / "out" / kCategoryClassifierFile), before);
  EXPECT_TRUE(fs::exists(dir / "out" / "refused" / kCategoryClassifierFile));
  EXPECT_EQ(readFileBytes(dir / "loaded" / kCategoryClassifierFile), before);
}

// Objects of one source cannot be left out while another teaches: retrained unguarded, and the
// panel says why and what would guard it.
TEST(CategoryGuardBySource, ATrainingSetOfOneSourceRetrainsUnguardedAndSaysSo) {
  const fs::path dir = test::freshTempDir();
  generateCurated(dir, false);
  saveLoaded(dir, CategoryClassifier::load(kShipped / kCategoryClassifierFile),
             {(dir / "gone").string()});

  const TrainingStatus status = retrainWithoutHeldOut(dir);
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 1u);
  EXPECT_EQ(
      status.verdicts[0].rfind("unguarded: the training set's objects come from one source", 0), 0u)
      << status.verdicts[0];
  EXPECT_NE(status.verdicts[0].find("a held-out folder of other sources guards it"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out" / kCategoryClassifierFile));
  EXPECT_FALSE(fs::exists(dir / "out" / "guard.jsonl"));
}

}  // namespace
}  // namespace sagrid::ui
