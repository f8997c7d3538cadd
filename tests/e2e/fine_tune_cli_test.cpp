// `sagrid train --init`: the exact fine-tuning form the README gives, run from the repository
// root on a folder of objects with labels.json (the real-dev layout, no manifest), one epoch and a
// tiny replay folder so it takes seconds.
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

TEST(FineTuneCli, InitFromShippedModelsOnARealDevStyleFolder) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 21}}, gen::MeshFormat::Obj, dir / "real");
  fs::remove(dir / "real" / "manifest.jsonl");  // object folders with labels.json only
  gen::generateDataset({{"stove", 1, 22}, {"sink", 1, 22}}, gen::MeshFormat::Obj, dir / "replay");
  const auto r = test::runSagridInSource(
      "train --data " + shellQuote((dir / "real").string()) +
      " --init resources/models --model stove.togglebutton --epochs 1 --replay " +
      shellQuote((dir / "replay").string()) + " --out " + shellQuote((dir / "out").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("stove.togglebutton: 2 objects"));
  const auto card =
      nlohmann::json::parse(readFileBytes(dir / "out" / "stove.togglebutton.json"));
  const auto shipped = nlohmann::json::parse(
      readFileBytes(fs::path(SAGRID_SOURCE_DIR) / "resources/models/stove.togglebutton.json"));
  EXPECT_EQ(card.at("architecture"), shipped.at("architecture"));
  // Choices about the model kept from the init card: the stove cards' crease patches.
  EXPECT_EQ(card.at("point_extraction").at("crease_patches"), true);
  const auto& training = card.at("training");
  EXPECT_DOUBLE_EQ(training.at("learning_rate").get<double>(), 1e-3);  // fine-tune default
  EXPECT_EQ(training.at("near_weight"), shipped.at("training").at("near_weight"));
  ASSERT_EQ(training.at("datasets").size(), 2u);
  EXPECT_EQ(training.at("datasets")[0].at("role"), "data");
  EXPECT_EQ(training.at("datasets")[0].at("sha256_of"), "labels.json files");
  EXPECT_EQ(training.at("datasets")[1].at("role"), "replay");
  EXPECT_EQ(training.at("datasets")[1].at("objects"), 1);  // the stove only
  // Replay drawn 1:1 with the new data by default.
  EXPECT_EQ(training.at("datasets")[1].at("weight"), training.at("datasets")[0].at("weight"));
  EXPECT_EQ(training.at("init").at("weights_sha256"), shipped.at("weights").at("sha256"));
  EXPECT_NE(card.at("weights").at("sha256"), shipped.at("weights").at("sha256"));
}

// --keep-init: the shipped network and card stay, the fine-tuned network joins them; without
// --init there is nothing to keep, and it says so before training.
TEST(FineTuneCli, KeepInitAddsTheFineTuneBesideTheShippedNetwork) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 23}}, gen::MeshFormat::Obj, dir / "real");
  gen::generateDataset({{"stove", 1, 24}}, gen::MeshFormat::Obj, dir / "replay");
  const std::string data = " --data " + shellQuote((dir / "real").string()) +
                           " --model stove.heatsource --epochs 1 --keep-init --out " +
                           shellQuote((dir / "out").string());
  const auto r = test::runSagridInSource("train" + data + " --init resources/models --replay " +
                                         shellQuote((dir / "replay").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto card = nlohmann::json::parse(readFileBytes(dir / "out" / "stove.heatsource.json"));
  const auto shipped = nlohmann::json::parse(
      readFileBytes(fs::path(SAGRID_SOURCE_DIR) / "resources/models/stove.heatsource.json"));
  EXPECT_EQ(card.at("weights").at("sha256"), shipped.at("weights").at("sha256"));
  EXPECT_EQ(card.at("point_extraction"), shipped.at("point_extraction"));
  ASSERT_EQ(card.at("weights").at("ensemble").size(), 1u);
  const auto& member = card.at("training").at("ensemble").back();
  EXPECT_EQ(member.at("role"), "fine-tune");
  EXPECT_THAT(member.at("command").get<std::string>(), HasSubstr("--keep-init"));
  EXPECT_TRUE(fs::exists(dir / "out" / card.at("weights").at("ensemble")[0].at("file").get<std::string>()));

  const auto refused = test::runSagridInSource("train" + data);
  EXPECT_NE(refused.exitCode, 0);
  EXPECT_THAT(refused.output, HasSubstr("--init"));
}

TEST(FineTuneCli, ReplayWithoutInitAndMismatchedArchitectureAreClearErrors) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 23}}, gen::MeshFormat::Obj, dir / "real");
  auto r = test::runSagrid("train --data " + shellQuote((dir / "real").string()) +
                           " --model stove.togglebutton --epochs 1 --replay " +
                           shellQuote((dir / "real").string()) + " --out " +
                           shellQuote((dir / "out").string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("give --init"));
  r = test::runSagrid(
      "train --data " + shellQuote((dir / "real").string()) + " --init " +
      shellQuote((fs::path(SAGRID_SOURCE_DIR) / "resources/models").string()) +
      " --model stove.togglebutton --replay none --arch '[3,1,8]' --epochs 1 --out " +
      shellQuote((dir / "out").string()));
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("architecture differs"));
  EXPECT_THAT(r.output, HasSubstr("[3,1,8]"));
}

// A guarded fine-tune that was interrupted (its candidate's checkpoint left beside the models)
// continues with --resume and ends with the guard's verdict; labels far from their mesh stop it
// before anything trains, and nothing is written.
TEST(FineTuneCli, AGuardedFineTuneResumesAndRefusesLabelsFarFromTheirMesh) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 24}}, gen::MeshFormat::Obj, dir / "real");
  gen::generateDataset({{"stove", 1, 25}}, gen::MeshFormat::Obj, dir / "held-out");
  gen::generateDataset({{"stove", 1, 26}}, gen::MeshFormat::Obj, dir / "replay");
  const std::string models = shellQuote((fs::path(SAGRID_SOURCE_DIR) / "resources/models").string());
  const std::string fineTune = "train --data " + shellQuote((dir / "real").string()) + " --init " +
                               models + " --model stove.togglebutton --epochs 3 --replay " +
                               shellQuote((dir / "replay").string());
  const std::string guard = " --guard " + shellQuote((dir / "held-out").string());
  const fs::path out = dir / "out";
  // The interrupted run: killed once its candidate's first checkpoint is written.
  const std::string checkpoint =
      shellQuote((out / ".candidate.stove.togglebutton" / "stove.togglebutton.checkpoint").string());
  auto r = test::runCommand(
      shellQuote(test::sagridBinary().string()) + " " + fineTune + guard + " --out " +
      shellQuote(out.string()) + " & pid=$!; timeout 300 sh -c 'until [ -f " + checkpoint +
      " ]; do sleep 0.05; done'; kill -9 $pid; wait $pid; test -f " + checkpoint);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "stove.togglebutton.pt"));
  r = test::runSagrid("--verbose " + fineTune + " --resume" + guard + " --out " + shellQuote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("resuming stove.togglebutton after epoch "));
  EXPECT_THAT(r.output, HasSubstr("held-out object(s): "));
  EXPECT_TRUE(fs::exists(out / "stove.togglebutton.pt"));
  EXPECT_TRUE(fs::exists(out / "guard.jsonl"));
  EXPECT_FALSE(fs::exists(out / ".candidate.stove.togglebutton"));

  // Labels in centimetres on a mesh in metres (x 100): refused before training, OUT untouched.
  const fs::path labelsFile = dir / "real" / "stove_s24_00000" / "labels.json";
  nlohmann::json labels = nlohmann::json::parse(readFileBytes(labelsFile));
  for (auto& point : labels.at("affordances"))
    for (auto& x : point.at("position")) x = x.get<double>() * 100;
  writeFileAtomic(labelsFile, labels.dump());
  const std::string before = readFileBytes(out / "stove.togglebutton.pt");
  r = test::runSagrid(fineTune + guard + " --out " + shellQuote(out.string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr(labelsFile.string()));
  EXPECT_THAT(r.output, HasSubstr("outside its mesh"));
  EXPECT_THAT(r.output, HasSubstr("the current model stays"));
  EXPECT_EQ(readFileBytes(out / "stove.togglebutton.pt"), before);
}

// Without a held-out folder the curated folders judge: the fine-tune is repeated with each
// source left out, OUT gets the adopted model or the current one, and guard.jsonl says by what.
// Curated objects of one source cannot judge: a clear error, and nothing is written.
TEST(FineTuneCli, TheGuardBySourceLeavesEachSourceOutInTurnAndNeedsTwo) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 27}}, gen::MeshFormat::Obj, dir / "repo-a");
  gen::generateDataset({{"stove", 1, 28}}, gen::MeshFormat::Obj, dir / "repo-b");
  gen::generateDataset({{"stove", 1, 26}}, gen::MeshFormat::Obj, dir / "replay");
  const fs::path models = fs::path(SAGRID_SOURCE_DIR) / "resources/models";
  const std::string fineTune = "train --init " + shellQuote(models.string()) +
                               " --model stove.togglebutton --epochs 1 --replay " +
                               shellQuote((dir / "replay").string()) + " --guard-by-source";
  const std::string both = " --data " + shellQuote((dir / "repo-a").string()) + " --data " +
                           shellQuote((dir / "repo-b").string());
  const fs::path out = dir / "out";
  auto r = test::runSagrid(fineTune + both + " --out " + shellQuote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("guard by source: fold 2/2"));
  EXPECT_THAT(r.output, HasSubstr("on 2 curated object(s) of 2 sources"));
  const nlohmann::json line = nlohmann::json::parse(readFileBytes(out / "guard.jsonl"));
  EXPECT_EQ(line.at("judged_by_source"), true);
  EXPECT_EQ(line.at("sources"), nlohmann::json({"repo-a", "repo-b"}));
  EXPECT_EQ(line.at("folds"), 2);
  EXPECT_EQ(line.at("objects"), 2);
  const bool adopted = line.at("adopted");
  // Adopted only where better by more than the paired noise of its objects.
  const double change =
      line.at("candidate_error_m").get<double>() - line.at("current_error_m").get<double>();
  EXPECT_EQ(adopted, change < -line.at("paired_noise_m").get<double>());
  // Refused: the current model in OUT; adopted: the fine-tune on both sources.
  EXPECT_EQ(readFileBytes(out / "stove.togglebutton.pt") ==
                readFileBytes(models / "stove.togglebutton.pt"),
            !adopted);
  EXPECT_FALSE(fs::exists(out / ".candidate.stove.togglebutton"));
  EXPECT_FALSE(fs::exists(out / ".guard-by-source.stove.togglebutton"));
  EXPECT_FALSE(fs::exists(out / "refused"));

  const fs::path alone = dir / "alone";
  r = test::runSagrid(fineTune + " --data " + shellQuote((dir / "repo-a").string()) + " --out " +
                      shellQuote(alone.string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("come from one source"));
  EXPECT_FALSE(fs::exists(alone / "stove.togglebutton.pt"));
  EXPECT_FALSE(fs::exists(alone / "guard.jsonl"));

  r = test::runSagrid(fineTune + both + " --guard " + shellQuote((dir / "replay").string()) +
                      " --out " + shellQuote(alone.string()));
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("excludes"));
}

}  // namespace
}  // namespace sagrid
