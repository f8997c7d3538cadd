// The learned point decision's file in a models folder: read back, refused with its reason, and
// applied by annotate to the models it decides for only.
#include "core/annotate/point_scorer.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>

#include <fstream>
#include <sstream>

#include "core/annotate/annotate.h"
#include "core/annotate/model_set.h"
#include "core/annotate/point_passes.h"
#include "core/annotate/units_record.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/dataset/dataset.h"
#include "core/features/feature_grid.h"
#include "core/generate/dataset_generator.h"
#include "core/points/point_count.h"
#include "support/point_scorers.h"
#include "support/test_paths.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

// A decision that finds no candidate good enough: the best one alone.
ModelPointScorer oneBest() { return test::fieldOnlyScorer(-10); }

// A decision that takes every candidate.
ModelPointScorer everyCandidate() {
  ModelPointScorer s = test::fieldOnlyScorer(10);
  s.choice.nmsRadius = 0;
  return s;
}

std::string messageOf(const fs::path& dir) {
  try {
    readPointScorer(dir);
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

TEST(PointScorerFile, ReadsBackWhatWasWrittenAndNamesWhatIsWrong) {
  const fs::path dir = test::freshTempDir();
  EXPECT_FALSE(readPointScorer(dir).has_value());  // no file: the passes' points stand
  PointScorer scorer;
  scorer.byModel["stove.togglebutton"] = oneBest();
  scorer.byModel["stove.togglebutton"].choice.copyThreshold = 0.2f;
  // A model decided by trees: only the trees are written and read.
  const std::size_t d = candidateFeatureNames().size();
  std::vector<std::vector<float>> rows;
  for (int i = 0; i < 20; ++i) rows.push_back(std::vector<float>(d, static_cast<float>(i % 2)));
  std::vector<bool> positive;
  for (int i = 0; i < 20; ++i) positive.push_back(i % 2 == 1);
  ModelPointScorer trees;
  trees.classifier.trees = fitBoostedTrees(rows, positive, std::vector<float>(20, 1.0f));
  // With a second look: trees over the features and the context features.
  std::vector<std::vector<float>> contextRows;
  for (const auto& row : rows) {
    contextRows.push_back(row);
    contextRows.back().resize(d + kContextFeatureCount, static_cast<float>(contextRows.size() % 2));
  }
  trees.classifier.contextTrees = fitBoostedTrees(contextRows, positive, std::vector<float>(20, 1.0f));
  // With a learned count: trees over the count's features and k.
  std::vector<std::vector<float>> countRows;
  for (int i = 0; i < 20; ++i)
    countRows.push_back(std::vector<float>(countFeatureNames().size(), static_cast<float>(i % 2)));
  trees.countTrees = fitBoostedTrees(countRows, positive, std::vector<float>(20, 1.0f));
  scorer.byModel["stove.heatsource"] = trees;
  scorer.byModel["stove.heatsource"].networkWeights = std::string(64, 'a');
  scorer.trainedOn = "test";
  writePointScorer(dir, scorer);
  const auto back = readPointScorer(dir);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(toJson(*back).dump(), toJson(scorer).dump());
  EXPECT_FALSE(toJson(scorer)["models"]["stove.heatsource"].contains("weights"));
  EXPECT_EQ(back->forModel("stove.heatsource")->networkWeights, std::string(64, 'a'));
  EXPECT_EQ(back->forModel("stove.togglebutton")->networkWeights, "");  // not recorded
  EXPECT_EQ(back->forModel("stove.togglebutton")->choice.copyThreshold, 0.2f);
  ASSERT_TRUE(back->forModel("stove.heatsource")->classifier.trees.has_value());
  EXPECT_GT(back->forModel("stove.heatsource")->classifier.probability(rows[1]), 0.5f);
  EXPECT_LT(back->forModel("stove.heatsource")->classifier.probability(rows[0]), 0.5f);
  ASSERT_TRUE(back->forModel("stove.heatsource")->classifier.contextTrees.has_value());
  EXPECT_EQ(toJson(*back->forModel("stove.heatsource")->classifier.contextTrees).dump(),
            toJson(*trees.classifier.contextTrees).dump());
  ASSERT_TRUE(back->forModel("stove.heatsource")->countTrees.has_value());
  EXPECT_FALSE(back->forModel("stove.togglebutton")->countTrees.has_value());

  auto j = toJson(scorer);
  auto rewrite = [&](const nlohmann::json& bad) { std::ofstream(dir / kPointScorerFile) << bad.dump(); };
  j["features"][1] = "renamed";
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("other candidate features"), std::string::npos);
  // Context trees of another build's context features: refused, naming the file and the count.
  j = toJson(scorer);
  j["models"]["stove.heatsource"]["context_trees"] = toJson(*trees.classifier.trees);
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("its context trees read " + std::to_string(d) + " features"),
            std::string::npos);
  EXPECT_NE(messageOf(dir).find(kPointScorerFile), std::string::npos);
  // Count trees of another build's count features, or beside a logistic regression: refused.
  j = toJson(scorer);
  j["count_features"][0] = "renamed";
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("other count features"), std::string::npos);
  j = toJson(scorer);
  j["models"]["stove.heatsource"]["count_trees"] = toJson(*trees.classifier.trees);
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("its count trees read " + std::to_string(d) + " features"),
            std::string::npos);
  j = toJson(scorer);
  j["models"]["stove.togglebutton"]["count_trees"] = toJson(*trees.countTrees);
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("count_trees need the trees of a first look"), std::string::npos);
  // A file from before the learned count: its choice alone decides.
  j = toJson(scorer);
  j.erase("count_features");
  j["models"]["stove.heatsource"].erase("count_trees");
  rewrite(j);
  EXPECT_FALSE(readPointScorer(dir)->forModel("stove.heatsource")->countTrees.has_value());
  j = toJson(scorer);
  j["context_features"][0] = "renamed";
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("other context features"), std::string::npos);
  j = toJson(scorer);
  j["models"]["stove.togglebutton"]["weights"][2] = nullptr;
  rewrite(j);
  EXPECT_NE(messageOf(dir).find(kPointScorerFile), std::string::npos);
  j = toJson(scorer);
  j["models"]["stove.togglebutton"]["scale"][0] = 0;
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("scales must be positive"), std::string::npos);
  // A file from before copies were taken has no copy threshold: its choice takes none.
  j = toJson(scorer);
  j["models"]["stove.togglebutton"].erase("copy_threshold");
  rewrite(j);
  EXPECT_GT(readPointScorer(dir)->forModel("stove.togglebutton")->choice.copyThreshold, 1.0f);
  j["models"]["stove.togglebutton"]["copy_threshold"] = "half";
  rewrite(j);
  EXPECT_NE(messageOf(dir).find(kPointScorerFile), std::string::npos);
  j = toJson(scorer);
  j["passes_off"] = {"mirror_pairs", "no_such_pass"};
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("unknown pass: no_such_pass"), std::string::npos);
  // A file written before the hand-set passes were removed names them off: they never run now.
  j["passes_off"] = {"printed_marks", "mirror_pairs", "part_ownership", "coarse_to_fine"};
  rewrite(j);
  EXPECT_EQ(readPointScorer(dir)->passesOff, std::vector<std::string>{"coarse_to_fine"});
  j = toJson(scorer);
  j["schema"] = "something/1";
  rewrite(j);
  EXPECT_NE(messageOf(dir).find("not a SAGrid point scorer"), std::string::npos);
}

class AnnotateWithScorer : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::freshTempDir();
    gen::generateDataset({{"stove", 1, 11}}, gen::MeshFormat::Glb, dir / "data");
    entries = readDataset(dir / "data");
    ASSERT_EQ(entries.size(), 1u);
    annotate.features.views = 12;
    features = extractFeatures(entries[0].mesh, annotate.features);
  }
  ModelSet models() const {
    std::vector<model::AffordanceModel> m;
    m.push_back(test::untrainedModelFor("stove.heatsource", features));
    m.push_back(test::untrainedModelFor("stove.togglebutton", features));
    return ModelSet(std::move(m));
  }
  std::vector<Eigen::Vector3f> pointsOf(const AnnotationResult& r, const std::string& type) {
    std::vector<Eigen::Vector3f> out;
    for (const auto* a : r.labels.ofType(type)) out.push_back(a->position);
    return out;
  }
  fs::path dir;
  std::ostringstream logged;
  std::vector<DatasetEntry> entries;
  FeatureGrid features;
  AnnotateOptions annotate;
};

TEST_F(AnnotateWithScorer, UnitsAProvenanceRecordDeclaresStandWithoutAGuess) {
  annotate.category = "stove";
  const auto guessed = annotateMeshFile(entries[0].mesh, "s", models(), annotate, dir / "a");
  EXPECT_TRUE(recordedUnitGuess(guessed.labels.object));
  EXPECT_FALSE(guessed.labels.object.extra.contains(kUnitsDeclaredByField));
  // The Sweet Home 3D corpus writes its catalog's scale beside each mesh.
  std::ofstream(entries[0].mesh.parent_path() / "provenance.json")
      << R"({"meters_per_unit": 0.2799})";
  const auto declared = annotateMeshFile(entries[0].mesh, "s", models(), annotate, dir / "b");
  EXPECT_FALSE(recordedUnitGuess(declared.labels.object));
  EXPECT_DOUBLE_EQ(declared.labels.object.extra.value("meters_per_unit", 0.0), 0.2799);
  EXPECT_EQ(declared.labels.object.extra.value(kUnitsDeclaredByField, std::string()),
            "provenance.json");
}

TEST_F(AnnotateWithScorer, ItDecidesForItsModelsOnlyAndIsSwitchedOff) {
  const ModelSet plain = models();
  ModelSet scored = models();
  PointScorer scorer;
  scorer.byModel["stove.togglebutton"] = oneBest();
  scored.setPointScorer(scorer, dir / kPointScorerFile);
  annotate.category = "stove";
  annotate.mode = InstanceMode::Auto;
  const auto passes = annotateMeshFile(entries[0].mesh, "s", plain, annotate, dir / "a");
  const auto decided = annotateMeshFile(entries[0].mesh, "s", scored, annotate, dir / "b");
  EXPECT_EQ(pointsOf(decided, "togglebutton").size(), 1u);
  // The category's evidence is the count's, whatever the scorer chooses (the gate was fitted on it).
  EXPECT_DOUBLE_EQ(decided.evidence, passes.evidence);
  EXPECT_GT(passes.evidence, 0.0);
  // labels.json says how its points were decided.
  EXPECT_EQ(decided.labels.extra.at("prediction").at("point_decision"), "learned");
  EXPECT_EQ(passes.labels.extra.at("prediction").at("point_decision"), "count");
  ModelSet every = models();
  PointScorer all;
  all.byModel["stove.togglebutton"] = everyCandidate();
  every.setPointScorer(all, dir / kPointScorerFile);
  EXPECT_GT(pointsOf(annotateMeshFile(entries[0].mesh, "s", every, annotate, dir / "d"), "togglebutton").size(),
            pointsOf(passes, "togglebutton").size());
  EXPECT_EQ(pointsOf(decided, "heatsource"), pointsOf(passes, "heatsource"));
  annotate.learnedDecision = false;
  const auto off = annotateMeshFile(entries[0].mesh, "s", scored, annotate, dir / "c");
  EXPECT_EQ(pointsOf(off, "togglebutton"), pointsOf(passes, "togglebutton"));

  // A scorer that learned from candidates made without the crop pass switches it off where it
  // decides; without the scorer, or switched off, the passes stay as given.
  PointScorer bare = scorer;
  bare.passesOff = {"coarse_to_fine"};
  ModelSet learnedBare = models();
  learnedBare.setPointScorer(bare, dir / kPointScorerFile);
  PassOptions given;
  const PassOptions used = withLearnedDecision(given, learnedBare);
  EXPECT_EQ(used.coarseToFine, std::optional<bool>(false));  // the crop pass, for every model
  // What the pipeline ran with is what candidates record: the crop pass counts as off only when
  // switched off for every model (unset, each card decides).
  EXPECT_EQ(passesOff(used), bare.passesOff);
  EXPECT_TRUE(passesOff(given).empty());
  EXPECT_EQ(used.scorer, learnedBare.pointScorer());
  given.learnedDecision = false;
  EXPECT_FALSE(withLearnedDecision(given, learnedBare).coarseToFine.has_value());
  EXPECT_EQ(withLearnedDecision(given, learnedBare).scorer, nullptr);
  EXPECT_FALSE(withLearnedDecision(PassOptions{}, plain).coarseToFine.has_value());

  // A decision learned from the candidates of other weights of its network still decides, and
  // loading it says so, naming the file and the model.
  auto messages = std::make_shared<spdlog::sinks::ostream_sink_mt>(logged);
  logger()->sinks().push_back(messages);
  PointScorer stale = scorer;
  stale.byModel["stove.togglebutton"].networkWeights = std::string(64, 'f');
  ModelSet staleSet = models();
  staleSet.setPointScorer(stale, dir / kPointScorerFile);
  logger()->sinks().pop_back();
  EXPECT_NE(logged.str().find("stove.togglebutton"), std::string::npos) << logged.str();
  EXPECT_NE(logged.str().find("other weights"), std::string::npos) << logged.str();
  EXPECT_NE(logged.str().find(kPointScorerFile), std::string::npos) << logged.str();
  EXPECT_EQ(pointsOf(annotateMeshFile(entries[0].mesh, "s", staleSet, annotate, dir / "e"),
                     "togglebutton").size(),
            1u);
  // Recorded and the card's own: nothing said.
  logged.str("");
  logger()->sinks().push_back(messages);
  PointScorer current = scorer;
  current.byModel["stove.togglebutton"].networkWeights =
      staleSet.forCategory("stove")[1]->card().weightsIdentity();
  ModelSet currentSet = models();
  currentSet.setPointScorer(current, dir / kPointScorerFile);
  logger()->sinks().pop_back();
  EXPECT_EQ(logged.str(), "");

  PointScorer stranger;
  stranger.byModel["sink.fluidsource"] = oneBest();
  ModelSet other = models();
  EXPECT_THROW(other.setPointScorer(stranger, dir / kPointScorerFile), ModelError);
}

}  // namespace
}  // namespace sagrid
