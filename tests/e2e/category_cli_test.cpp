// sagrid category evidence | eval --evidence from the command line: the gate fitted into a copy of
// the shipped models folder for the asked category only, the evaluation through it, and a clear
// error where the folder's classifier has no gate.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/annotate/category_classifier.h"
#include "core/generate/dataset_generator.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::quotedPath;
using test::runSagrid;
using ::testing::HasSubstr;
using ::testing::Not;

TEST(CategoryCli, EvidenceFitsTheGateOfTheAskedCategoryAndEvalUsesItSlow) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 3, 11}, {"sink", 1, 12}, {"none", 2, 13}}, gen::MeshFormat::Obj,
                       dir / "data");
  const fs::path models = dir / "models";
  fs::copy(fs::path(SAGRID_SOURCE_DIR) / "resources" / "models", models,
           fs::copy_options::recursive);
  auto classifier = CategoryClassifier::load(models / kCategoryClassifierFile);
  classifier.evidence = {};  // as before any gate was fitted
  classifier.save(models / kCategoryClassifierFile);

  const std::string data = " --data " + quotedPath(dir / "data") + " --models " +
                           quotedPath(models) + " --cache " + quotedPath(dir / "cache");
  // Without a gate, --evidence is a clear error naming the folder.
  auto r = runSagrid("category eval" + data + " --evidence");
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("evidence gate"));
  EXPECT_THAT(r.output, HasSubstr(models.string()));

  r = runSagrid("category evidence" + data + " --category stove --keep 1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("| stove | 3 |"));
  EXPECT_THAT(r.output, Not(HasSubstr("| sink |")));
  const auto gated = CategoryClassifier::load(models / kCategoryClassifierFile);
  ASSERT_EQ(gated.evidence.thresholds.size(), 1u);
  // --keep 1: the threshold is the least evidence of the three stoves, so all three keep it.
  EXPECT_GT(gated.evidence.thresholds.at("stove"), 0.0);
  EXPECT_EQ(gated.evidence.record.at("kept").at("stove"), 3);
  EXPECT_EQ(gated.evidence.record.at("distractors_below").at("stove").at(1), 2);
  EXPECT_EQ(gated.evidence.modelShas.count("stove.heatsource"), 1u);

  r = runSagrid("category eval" + data + " --evidence");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("| stoves right | 3 |"));
}

}  // namespace
}  // namespace sagrid
