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
  const auto r = test::runCommand(
      "cd " + shellQuote(SAGRID_SOURCE_DIR) + " && " + shellQuote(test::sagridBinary().string()) +
      " eval --learning-curve --data " + shellQuote((dir / "linked").string()) +
      " --init resources/models --model stove.heatsource --ks 0,1 --folds 2 --epochs 1 --replay " +
      shellQuote((dir / "replay").string()) + " --out " + shellQuote((dir / "lc").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("fold 2/2 k=1 stove.heatsource: fine-tuned on 1 object(s)"));
  const auto report = nlohmann::json::parse(readFileBytes(dir / "lc" / "learning_curve.json"));
  ASSERT_EQ(report.at("folds").size(), 2u);
  EXPECT_EQ(report.at("folds")[0].size() + report.at("folds")[1].size(), 2u);
}

}  // namespace
}  // namespace sagrid
