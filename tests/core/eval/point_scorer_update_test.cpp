#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/eval/point_scorer_update.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;

// `scorer update` and the GUI's "Retrain point decision" learn from the generated objects the
// shipped decision learned from: the bench's val split and its decision split, both made once.
TEST(PointScorerUpdate, LearnsFromTheBenchsValAndDecisionSplitsGeneratedOnce) {
  const fs::path bench = test::freshTempDir();
  fs::create_directories(bench / "val");
  std::ofstream(bench / "val" / "manifest.jsonl") << "";  // the bench as a curator already has it
  int progress = 0;
  const auto dirs = decisionGeneratedDirs(bench, [&](int, int) { ++progress; });
  ASSERT_EQ(dirs.size(), 2u);
  EXPECT_EQ(dirs[0], bench / "val");
  EXPECT_EQ(dirs[1], bench / "decision");
  std::ifstream manifest(bench / "decision" / "manifest.jsonl");
  int objects = 0;
  for (std::string line; std::getline(manifest, line);) objects += !line.empty();
  EXPECT_EQ(objects, 120) << "the decision split is generated where it is missing";
  EXPECT_EQ(progress, 120);
  EXPECT_EQ(std::ifstream(bench / "val" / "manifest.jsonl").peek(), EOF) << "val left as it was";

  progress = 0;
  EXPECT_EQ(decisionGeneratedDirs(bench, [&](int, int) { ++progress; }), dirs);
  EXPECT_EQ(progress, 0) << "both splits are there: nothing generated again";
}

}  // namespace
}  // namespace sagrid
