// sagrid scorer update from the command line (issue 40, item 1): the models folder's point
// decision retrained from curated objects in one step, as the GUI's Train panel does; a missing
// folder, or a held-out folder that is also training data, is one clear error and nothing is
// written. `scorer train` refuses candidates of other networks than its models folder's.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/annotate/point_scorer.h"
#include "core/dataset/dataset.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "core/model/model_card.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::quotedPath;
using test::runSagrid;
using ::testing::HasSubstr;

TEST(ScorerUpdateCli, WritesTheModelsFolderWithTheVerdictAndRefusesHeldOutTrainingData) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 71}, {"sink", 1, 72}}, gen::MeshFormat::Obj, dir / "curated");
  gen::generateDataset({{"stove", 1, 73}, {"sink", 1, 74}}, gen::MeshFormat::Obj, dir / "generated");
  gen::generateDataset({{"stove", 1, 75}, {"sink", 1, 76}}, gen::MeshFormat::Obj, dir / "held-out");
  const std::string common = " --data " + quotedPath(dir / "curated") + " --generated " +
                             quotedPath(dir / "generated") + " --out " + quotedPath(dir / "out");

  // A folder that is not there is named before any candidate is made.
  auto r = runSagrid("scorer update" + common + " --held-out " + quotedPath(dir / "gone"));
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr((dir / "gone").string() + ": dataset folder not found"));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("candidates, curated")));

  r = runSagrid("scorer update" + common + " --held-out " + quotedPath(dir / "curated"));
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("stove_s71_00000"));
  EXPECT_FALSE(fs::exists(dir / "out" / kPointScorerFile));

  r = runSagrid("scorer update" + common + " --held-out " + quotedPath(dir / "held-out"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("4 curated, 4 generated, 4 held-out model sets"));
  const bool adopted = r.output.find("): adopted") != std::string::npos;
  EXPECT_TRUE(adopted || r.output.find("refused, the current decision stays") != std::string::npos)
      << r.output;
  // The folder written is a whole models folder: the networks copied, and a scorer either way.
  EXPECT_TRUE(fs::exists(dir / "out" / "stove.heatsource.json"));
  EXPECT_TRUE(fs::exists(dir / "out" / "scorer_guard.json"));
  EXPECT_TRUE(readPointScorer(adopted ? dir / "out" : dir / "out" / "refused").has_value());
  // The decision records the networks its candidates came from: the folder's own.
  const auto written = readPointScorer(adopted ? dir / "out" : dir / "out" / "refused");
  for (const auto& [model, decision] : written->byModel)
    EXPECT_EQ(decision.networkWeights,
              model::readModelCard(dir / "out" / (model + ".json")).weightsIdentity())
        << model;
  // One line per model says whether its new decision was adopted.
  EXPECT_THAT(r.output, ::testing::ContainsRegex("guard: stove\\.[a-z]+: [0-9]+ -> [0-9]+ edits on "
                                                 "[0-9]+ held-out points: (adopted|the decision "
                                                 "before stays)"));
}

// Without a held-out folder the curated objects judge, each source left out of the fitting in
// turn (issue 40: folds by source); curated objects of one source are retrained unguarded, and
// the verdict says so.
TEST(ScorerUpdateCli, WithoutAHeldOutFolderTheCuratedSourcesJudge) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 81}, {"sink", 2, 82}}, gen::MeshFormat::Obj, dir / "curated");
  gen::generateDataset({{"stove", 1, 83}, {"sink", 1, 84}}, gen::MeshFormat::Obj,
                       dir / "generated");
  test::assignSources(dir / "curated", {"repo-a", "repo-b"});
  for (const auto& entry : readDataset(dir / "curated")) {  // curated as real objects are
    ObjectLabels labels = readLabels(entry.labels);
    labels.object.extra.erase("generator");
    writeLabels(entry.labels, labels);
  }
  const std::string common = " --data " + quotedPath(dir / "curated") + " --generated " +
                             quotedPath(dir / "generated") + " --out " + quotedPath(dir / "out");
  auto r = runSagrid("scorer update" + common);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, ::testing::ContainsRegex(
                            "[0-9]+ -> [0-9]+ edits on the curated objects, each source of 2 left "
                            "out of the fitting in turn \\(the current point decision -> the "
                            "retrained one\\): (adopted|refused)"));
  EXPECT_TRUE(fs::exists(dir / "out" / "scorer_guard.json"));

  test::assignSources(dir / "curated", {"repo-a"});
  r = runSagrid("scorer update" + common);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("unguarded: the curated objects come from one source"));
}

// Candidates made by other networks than the models folder's: `scorer train` refuses to write a
// decision for them, naming the model and what to run.
TEST(ScorerTrainCli, RefusesCandidatesOfOtherNetworksThanTheModelsFolders) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 81}}, gen::MeshFormat::Obj, dir / "data");
  const fs::path candidates = dir / "candidates.json";
  auto r = runSagrid("scorer candidates --data " + quotedPath(dir / "data") + " --out " +
                     quotedPath(candidates));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  nlohmann::json j;
  std::ifstream(candidates) >> j;
  for (auto& set : j["sets"]) set["network_weights"] = std::string(64, 'e');
  std::ofstream(dir / "other.json") << j.dump();
  r = runSagrid("scorer train --candidates " + quotedPath(dir / "other.json") + " --out " +
                quotedPath(dir / "out"));
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("made by other weights (eeeeeeee)"));
  EXPECT_THAT(r.output, HasSubstr("sagrid scorer candidates --models"));
  EXPECT_FALSE(fs::exists(dir / "out" / kPointScorerFile));
  // The same candidates as made: trained and written.
  r = runSagrid("scorer train --candidates " + quotedPath(candidates) + " --out " +
                quotedPath(dir / "out"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(readPointScorer(dir / "out").has_value());
}

// Candidates on the mesh's crease patches: made for the models whose card says so (the shipped
// stove cards) and for no other.
TEST(ScorerCandidatesCli, CreasePatchesGiveCandidatesWhereTheModelsCardSaysSo) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 85}}, gen::MeshFormat::Obj, dir / "data");
  const fs::path models = dir / "models";
  fs::copy(fs::path(SAGRID_SOURCE_DIR) / "resources/models", models);
  fs::remove(models / kPointScorerFile);  // learned on the shipped candidates; not needed here
  const auto onPatches = [&] {
    const fs::path out = dir / "candidates.json";
    const auto r = runSagrid("scorer candidates --models " + quotedPath(models) + " --data " +
                             quotedPath(dir / "data") + " --out " + quotedPath(out));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json j;
    std::ifstream(out) >> j;
    const auto& names = j.at("features");
    const auto column = std::find(names.begin(), names.end(), "part_by_crease") - names.begin();
    int count = 0;
    for (const auto& set : j.at("sets"))
      for (const auto& features : set.at("features")) count += features.at(column) == 1.0;
    return count;
  };
  const auto switchCards = [&](bool on) {
    for (const char* model : {"stove.heatsource", "stove.togglebutton"}) {
      const fs::path card = models / (std::string(model) + ".json");
      nlohmann::json j;
      std::ifstream(card) >> j;
      EXPECT_EQ(j["point_extraction"]["crease_patches"], !on) << model;  // shipped on
      j["point_extraction"]["crease_patches"] = on;
      std::ofstream(card) << j.dump(2);
    }
  };
  EXPECT_GT(onPatches(), 0);
  switchCards(false);
  EXPECT_EQ(onPatches(), 0);
}

}  // namespace
}  // namespace sagrid
