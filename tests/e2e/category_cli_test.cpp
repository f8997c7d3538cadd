// sagrid category evidence | eval --evidence from the command line: the gate fitted into a copy of
// the shipped models folder for the asked category only, the evaluation through it, and a clear
// error where the folder's classifier has no gate.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "core/annotate/category_classifier.h"
#include "core/common/atomic_file.h"
#include "core/generate/dataset_generator.h"
#include "support/labelled_objects.h"
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

// After a refused classifier update: the shipped file `shipped` untouched in `models`, the
// candidate in refused/; the first line of the guard's log.
std::string guardLineOfRefusal(const fs::path& models, const std::string& shipped) {
  EXPECT_EQ(readFileBytes(models / kCategoryClassifierFile), shipped);
  EXPECT_TRUE(fs::exists(models / "refused" / kCategoryClassifierFile));
  std::ifstream log(models / "guard.jsonl");
  std::string line;
  EXPECT_TRUE(std::getline(log, line)) << "no guard.jsonl line";
  return line;
}

// The guard on classifier updates (issue 40): a classifier trained for one step decides the
// held-out objects worse than the shipped one and is refused (written to OUT/refused/, the
// shipped file untouched), and the verdict is logged.
TEST(CategoryCli, TheGuardRefusesAWorseClassifierAndKeepsTheCurrentOne) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 3, 41}, {"sink", 3, 42}, {"none", 3, 43}}, gen::MeshFormat::Obj,
                       dir / "train");
  gen::generateDataset({{"stove", 2, 44}, {"sink", 2, 45}, {"none", 2, 46}}, gen::MeshFormat::Obj,
                       dir / "held-out");
  const fs::path models = dir / "models";
  fs::copy(fs::path(SAGRID_SOURCE_DIR) / "resources" / "models", models,
           fs::copy_options::recursive);
  const std::string shipped = readFileBytes(models / kCategoryClassifierFile);
  const std::string train = "category train --data " + quotedPath(dir / "train") + " --out " +
                            quotedPath(models) + " --guard " + quotedPath(dir / "held-out");
  auto r = runSagrid(train + " --iterations 1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("refused, current classifier kept"));
  EXPECT_THAT(guardLineOfRefusal(models, shipped), HasSubstr("\"adopted\":false"));

  // Held-out objects of one class cannot judge a classifier (calling everything a stove would
  // score best there): refused with the reason, nothing written.
  fs::remove_all(models / "refused");
  gen::generateDataset({{"stove", 2, 47}}, gen::MeshFormat::Obj, dir / "stoves");
  r = runSagrid("category train --data " + quotedPath(dir / "train") + " --out " +
                quotedPath(models) + " --guard " + quotedPath(dir / "stoves") +
                " --iterations 1");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("hold only stove objects"));
  EXPECT_EQ(readFileBytes(models / kCategoryClassifierFile), shipped);
  EXPECT_FALSE(fs::exists(models / "refused"));
}

// The guard judged by source (issue 40: folds by source): the curated objects of two repositories
// judge the one-step recipe against the shipped classifier, whose training folders are not here
// (judged as it is): refused, logged by source. A curated folder of one source, or both guards at
// once, are clear errors with nothing written.
TEST(CategoryCli, TheGuardBySourceRefusesAWorseRecipe) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 48}, {"sink", 2, 49}, {"none", 2, 50}}, gen::MeshFormat::Obj,
                       dir / "curated");
  test::assignSources(dir / "curated", {"repo-a", "repo-b"});
  const fs::path models = dir / "models";
  fs::copy(fs::path(SAGRID_SOURCE_DIR) / "resources" / "models", models,
           fs::copy_options::recursive);
  const std::string shipped = readFileBytes(models / kCategoryClassifierFile);
  const std::string train = "category train --data " + quotedPath(dir / "curated") + " --out " +
                            quotedPath(models) + " --iterations 1";
  auto r = runSagrid(train + " --guard-by-source " + quotedPath(dir / "curated"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("each source of 2 left out of training in turn (the current "
                                  "classifier as it is"));
  EXPECT_THAT(r.output, HasSubstr("refused, current classifier kept"));
  const std::string line = guardLineOfRefusal(models, shipped);
  EXPECT_THAT(line, HasSubstr("\"judged_by_source\""));
  EXPECT_THAT(line, HasSubstr("\"sources\":2"));

  fs::remove_all(models / "refused");
  test::assignSources(dir / "curated", {"repo-a"});
  r = runSagrid(train + " --guard-by-source " + quotedPath(dir / "curated"));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("one source only (repo-a)"));
  r = runSagrid(train + " --guard-by-source " + quotedPath(dir / "curated") + " --guard " +
                quotedPath(dir / "curated"));
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("excludes"));
  EXPECT_EQ(readFileBytes(models / kCategoryClassifierFile), shipped);
  EXPECT_FALSE(fs::exists(models / "refused"));
}

// `category cv --decisions`: every validated object's decision as a JSON line, with the
// probabilities as decided and from the shape alone, for analyses outside the product.
TEST(CategoryCli, CrossValidationWritesEachObjectsDecision) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 51}, {"sink", 2, 52}, {"none", 2, 53}}, gen::MeshFormat::Obj,
                       dir / "train");
  gen::generateDataset({{"stove", 2, 54}, {"sink", 2, 55}, {"none", 2, 56}}, gen::MeshFormat::Obj,
                       dir / "curated");
  test::assignSources(dir / "curated", {"repo-a", "repo-b"});
  const fs::path file = dir / "decisions.jsonl";
  const auto r = runSagrid("category cv --data " + quotedPath(dir / "train") + " --validate " +
                           quotedPath(dir / "curated") + " --by-source --iterations 1 --file-name" +
                           " --decisions " + quotedPath(file));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(file);
  std::string line;
  std::set<std::string> sources;
  int lines = 0;
  while (std::getline(in, line)) {
    const auto j = nlohmann::json::parse(line);
    ++lines;
    sources.insert(j.at("source").get<std::string>());
    EXPECT_TRUE(fs::exists(j.at("mesh").get<std::string>()));
    double sum = 0;
    for (const auto& [cls, p] : j.at("probabilities").items()) sum += p.get<double>();
    EXPECT_NEAR(sum, 1.0, 1e-9) << line;
    EXPECT_EQ(j.at("shape_probabilities").size(), j.at("probabilities").size());
    // Generated files are all "mesh.obj": no curated name taught a word, so nothing moved them.
    EXPECT_TRUE(j.at("name_words").empty());
    EXPECT_EQ(j.at("name_weight"), 1.0);  // no curated name to learn a weight from
    EXPECT_EQ(j.at("probabilities"), j.at("shape_probabilities"));
    EXPECT_THAT(std::string("stove sink none"), HasSubstr(j.at("truth").get<std::string>()));
  }
  EXPECT_EQ(lines, 6);
  EXPECT_EQ(sources, (std::set<std::string>{"repo-a", "repo-b"}));
}

}  // namespace
}  // namespace sagrid
