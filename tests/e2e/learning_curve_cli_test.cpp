// `sagrid eval --learning-curve` on a dataset whose object folders are symbolic links to objects
// elsewhere (a curated set assembled with `ln -s`): the folds reach the linked objects, as every
// other command that reads the dataset does.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/generate/dataset_generator.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::shellQuote;
using ::testing::HasSubstr;

TEST(LearningCurveCli, FoldsReachObjectFoldersLinkedFromElsewhere) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 31}}, gen::MeshFormat::Obj, dir / "store");
  gen::generateDataset({{"stove", 1, 32}}, gen::MeshFormat::Obj, dir / "replay");
  fs::create_directories(dir / "linked");
  for (const auto& e : fs::directory_iterator(dir / "store")) {
    if (e.is_directory())
      fs::create_directory_symlink(e.path(), dir / "linked" / e.path().filename());
  }
  const auto r = test::runSagridInSource(
      "eval --learning-curve --data " + shellQuote((dir / "linked").string()) +
      " --init resources/models --model stove.heatsource --ks 0,1 --folds 2 --epochs 1 --replay " +
      shellQuote((dir / "replay").string()) + " --out " + shellQuote((dir / "lc").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("fold 2/2 k=1 stove.heatsource: fine-tuned on 1 object(s)"));
  const auto report = nlohmann::json::parse(readFileBytes(dir / "lc" / "learning_curve.json"));
  ASSERT_EQ(report.at("folds").size(), 2u);
  EXPECT_EQ(report.at("folds")[0].size() + report.at("folds")[1].size(), 2u);
}

// --keep-init: each fold's fine-tune joins the shipped network (one member of role "fine-tune"
// under the shipped card), and the report says so.
TEST(LearningCurveCli, KeepInitEvaluatesEachFineTuneBesideTheShippedNetwork) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 33}}, gen::MeshFormat::Obj, dir / "data");
  gen::generateDataset({{"stove", 1, 34}}, gen::MeshFormat::Obj, dir / "replay");
  const auto r = test::runSagridInSource(
      "eval --learning-curve --data " + shellQuote((dir / "data").string()) +
      " --init resources/models --model stove.heatsource --ks 0,1 --folds 2 --epochs 1 --keep-init"
      " --replay " + shellQuote((dir / "replay").string()) + " --out " + shellQuote((dir / "lc").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto report = nlohmann::json::parse(readFileBytes(dir / "lc" / "learning_curve.json"));
  EXPECT_EQ(report.at("keep_init"), true);
  EXPECT_THAT(readFileBytes(dir / "lc" / "learning_curve.md"),
              HasSubstr("the init model's networks kept beside the fine-tuned one"));
  const auto shipped = nlohmann::json::parse(
      readFileBytes(fs::path(SAGRID_SOURCE_DIR) / "resources/models/stove.heatsource.json"));
  for (const char* fold : {"fold1", "fold2"}) {
    const auto card = nlohmann::json::parse(
        readFileBytes(dir / "lc" / "work" / fold / "k1" / "models" / "stove.heatsource.json"));
    EXPECT_EQ(card.at("weights").at("sha256"), shipped.at("weights").at("sha256")) << fold;
    ASSERT_EQ(card.at("weights").at("ensemble").size(), 1u) << fold;
    EXPECT_EQ(card.at("training").at("ensemble")[0].at("role"), "fine-tune") << fold;
  }
}

// --guard: each fold's training sources are split into the fine-tune pool and a guard set of
// other sources, every fine-tune is judged there, and the report says which were kept.
TEST(LearningCurveCli, AGuardedCurveJudgesEveryFineTuneOnSourcesItDidNotTrainOn) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 3, 33}}, gen::MeshFormat::Obj, dir / "real");
  gen::generateDataset({{"stove", 1, 34}}, gen::MeshFormat::Obj, dir / "replay");
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir / "real"))
    if (e.is_directory())
      writeFileAtomic(e.path() / "provenance.json", "{\"repo\": \"owner/source" + std::to_string(n++) + "\"}");
  const auto r = test::runSagridInSource(
      "eval --learning-curve --by-source --guard --data " + shellQuote((dir / "real").string()) +
      " --init resources/models --model stove.heatsource --ks 0,1 --folds 3 --epochs 1 --replay " +
      shellQuote((dir / "replay").string()) + " --out " + shellQuote((dir / "lc").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("fold 1: guard set of 1 object(s), fine-tunes drawn from 1"));
  EXPECT_THAT(r.output, HasSubstr("k=1 stove.heatsource: guard: "));
  EXPECT_THAT(r.output, HasSubstr("held-out object(s): "));
  const auto report = nlohmann::json::parse(readFileBytes(dir / "lc" / "learning_curve.json"));
  EXPECT_TRUE(report.at("guarded").get<bool>());
  int fineTunes = 0;
  for (const auto& point : report.at("points"))
    if (point.at("k_used").get<int>() == 1) {
      ++fineTunes;
      EXPECT_TRUE(point.contains("adopted"));
    }
  EXPECT_EQ(fineTunes, 3);
  EXPECT_THAT(readFileBytes(dir / "lc" / "learning_curve.md"), HasSubstr("Guarded: each fine-tune"));
}

}  // namespace
}  // namespace sagrid
