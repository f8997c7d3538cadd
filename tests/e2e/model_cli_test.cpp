// sagrid train / annotate / filter / eval from the command line: bad input gives one clear error,
// a directory with a broken mesh is annotated except for that mesh, reports are written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "core/annotate/point_scorer.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::runSagrid;
using test::shellQuote;
using ::testing::HasSubstr;

const std::string kModels =
    shellQuote((fs::path(SAGRID_SOURCE_DIR) / "resources" / "models").string());

TEST(ModelCli, TrainRejectsEmptyDatasetsMissingCategoriesAndBadArchitectures) {
  const fs::path dir = test::freshTempDir();
  fs::create_directories(dir / "empty");
  auto r = runSagrid("train --data " + shellQuote((dir / "empty").string()) +
                     " --model stove.heatsource --out " + shellQuote((dir / "m").string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("has no objects"));

  gen::generateDataset({{"sink", 2, 3}}, gen::MeshFormat::Obj, dir / "sinks");
  r = runSagrid("train --data " + shellQuote((dir / "sinks").string()) +
                " --model stove.heatsource --out " + shellQuote((dir / "m").string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("no stove objects"));

  r = runSagrid("train --data " + shellQuote((dir / "sinks").string()) +
                " --model sink.fluidsource --arch '[3,1,16],[3,1,8,2]'");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("layer 2: padding 1"));

  r = runSagrid("train --data " + shellQuote((dir / "sinks").string()) + " --model sinkfluid");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("<category>.<type>"));
}

TEST(ModelCli, TrainWritesWeightsCardAndLossCurve) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"sink", 2, 4}}, gen::MeshFormat::Obj, dir / "data");
  const auto r =
      runSagrid("train --data " + shellQuote((dir / "data").string()) +
                " --model sink.fluidsource --arch '[3,1,4],[3,2,4,2]' --epochs 2 --out " +
                shellQuote((dir / "m").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* f : {"sink.fluidsource.json", "sink.fluidsource.pt", "sink.fluidsource.loss.csv",
                        "sink.fluidsource.loss.png"})
    EXPECT_TRUE(fs::exists(dir / "m" / f)) << f;
  EXPECT_FALSE(fs::exists(dir / "m" / "sink.fluidsource.checkpoint"));  // removed once finished
  EXPECT_THAT(r.output, HasSubstr("sink.fluidsource: 2 objects"));
}

TEST(ModelCli, AnnotateReportsABrokenMeshAndCarriesOn) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 9}}, gen::MeshFormat::Obj, dir / "in");
  std::ofstream(dir / "in" / "broken.obj") << "v 0 0 0\nf 1 2 3\n";
  const auto r = runSagrid("annotate " + shellQuote((dir / "in").string()) + " --models " +
                           kModels + " --category stove --out " + shellQuote((dir / "out").string()));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("broken.obj: failed"));
  EXPECT_THAT(r.output, HasSubstr("annotated 1 of 2 objects"));
  const fs::path labels = dir / "out" / "stove_s9_00000" / "labels.json";
  ASSERT_TRUE(fs::exists(labels)) << r.output;
  const ObjectLabels l = readLabels(labels);
  EXPECT_EQ(l.object.category, "stove");
  EXPECT_FALSE(l.ofType("heatsource").empty());
  EXPECT_FALSE(l.ofType("togglebutton").empty());
  EXPECT_THAT(l.affordances.front().source, HasSubstr("stove."));
}

TEST(ModelCli, EvalAndFilterWriteTheirReports) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 11}, {"sink", 2, 11}}, gen::MeshFormat::Mixed, dir / "data");
  auto r = runSagrid("eval --data " + shellQuote((dir / "data").string()) + " --models " + kModels +
                     " --out " + shellQuote((dir / "eval").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("| SAGrid argmin (paper) |"));
  EXPECT_THAT(r.output, HasSubstr("Embedding search L2"));
  for (const char* f : {"eval.md", "eval.json", "eval.png"})
    EXPECT_TRUE(fs::exists(dir / "eval" / f)) << f;
  // Per object: the paper's single-point error of each model is the distance of its argmin point
  // to the nearest truth, and eval.md has a row for the object.
  std::ifstream jsonFile(dir / "eval" / "eval.json");
  const auto report = nlohmann::json::parse(jsonFile);
  std::ifstream mdFile(dir / "eval" / "eval.md");
  const std::string md((std::istreambuf_iterator<char>(mdFile)), std::istreambuf_iterator<char>());
  EXPECT_THAT(md, HasSubstr("## Per object"));
  int checked = 0;
  for (const auto& object : report.at("per_object")) {
    EXPECT_THAT(md, HasSubstr("| " + object.at("id").get<std::string>() + " |"));
    for (const auto& [model, error] : object.at("paper_error_m").items()) {
      const auto p = object.at("predictions").at(model).at("SAGrid argmin (paper)").at(0);
      double nearest = 1e30;
      for (const auto& t : object.at("truth").at(model))
        nearest = std::min(nearest, std::hypot(p[0].get<double>() - t[0].get<double>(),
                                               p[1].get<double>() - t[1].get<double>(),
                                               p[2].get<double>() - t[2].get<double>()));
      EXPECT_NEAR(error.get<double>(), nearest * object.at("meters_per_unit").get<double>(), 1e-6);
      ++checked;
    }
  }
  EXPECT_GE(checked, 8);  // 4 objects x 2 models of their category

  r = runSagrid("filter " + shellQuote((dir / "data").string()) + " --like stove --models " +
                kModels);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("mesh."));
}

// The points annotate writes for the one object of `in`, in file order.
std::vector<Eigen::Vector3f> annotatedPoints(const fs::path& in, const std::string& models,
                                             const std::string& flags, const fs::path& out) {
  const auto r = runSagrid("annotate " + shellQuote(in.string()) + " --models " + models +
                           " --category sink " + flags + " --out " + shellQuote(out.string()));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::vector<Eigen::Vector3f> points;
  for (const auto& entry : fs::directory_iterator(out))
    if (fs::exists(entry.path() / "labels.json"))
      for (const auto& a : readLabels(entry.path() / "labels.json").affordances)
        points.push_back(a.position);
  return points;
}

// The shipped models with both sink cards' point_extraction.coarse_to_fine set to `on`, without
// the learned point decision (it switches the crop pass off where it decides).
std::string modelsWithSecondPass(const fs::path& dir, bool on) {
  fs::copy(fs::path(SAGRID_SOURCE_DIR) / "resources" / "models", dir);
  fs::remove(dir / kPointScorerFile);
  for (const char* name : {"sink.fluidsource.json", "sink.togglebutton.json"}) {
    nlohmann::json card = nlohmann::json::parse(std::ifstream(dir / name));
    card["point_extraction"]["coarse_to_fine"] = on;
    std::ofstream(dir / name) << card.dump(2);
  }
  return shellQuote(dir.string());
}

TEST(ModelCli, TheSecondPassRunsWhereTheCardSaysUnlessTheCommandLineSaysOtherwise) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"sink", 1, 21}}, gen::MeshFormat::Obj, dir / "in");
  const std::string on = modelsWithSecondPass(dir / "on", true);
  const std::string off = modelsWithSecondPass(dir / "off", false);
  const auto cardSaysOn = annotatedPoints(dir / "in", on, "", dir / "a");
  const auto forcedOn = annotatedPoints(dir / "in", off, "--coarse-to-fine", dir / "b");
  const auto forcedOff = annotatedPoints(dir / "in", on, "--no-coarse-to-fine", dir / "c");
  const auto cardSaysOff = annotatedPoints(dir / "in", off, "", dir / "d");
  ASSERT_FALSE(cardSaysOff.empty());
  EXPECT_EQ(cardSaysOn, forcedOn);
  EXPECT_EQ(forcedOff, cardSaysOff);
  // On this object the second pass moves the points, so the equalities above tell them apart.
  EXPECT_NE(cardSaysOn, cardSaysOff);
}

}  // namespace
}  // namespace sagrid
