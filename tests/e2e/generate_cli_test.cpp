// `sagrid generate` and `sagrid dataset-stats` end to end: exit codes, dataset layout, determinism,
// the bench preset's counts, contact sheet written.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using test::runSagrid;
using test::shellQuote;

int lineCount(const fs::path& file) {
  std::ifstream in(file);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty();
  return n;
}

TEST(GenerateCli, WritesDatasetDeterministicallyWithContactSheet) {
  const fs::path dir = test::freshTempDir();
  const auto r = runSagrid("generate --category sink --count 5 --seed 9 --out " + shellQuote((dir / "a").string()) +
                           " --contact-sheet " + shellQuote((dir / "sheet.png").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(lineCount(dir / "a" / "manifest.jsonl"), 5);
  EXPECT_TRUE(fs::exists(dir / "a" / "sink_s9_00004" / "labels.json"));
  EXPECT_EQ(readFileBytes(dir / "sheet.png").substr(1, 3), "PNG");
  const auto again = runSagrid("generate --category sink --count 5 --seed 9 --out " + shellQuote((dir / "b").string()));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(readFileBytes(dir / "a" / "manifest.jsonl"), readFileBytes(dir / "b" / "manifest.jsonl"));
  EXPECT_EQ(readFileBytes(dir / "a" / "sink_s9_00003" / "labels.json"),
            readFileBytes(dir / "b" / "sink_s9_00003" / "labels.json"));

  const auto stats = runSagrid("dataset-stats " + shellQuote((dir / "a").string()));
  ASSERT_EQ(stats.exitCode, 0) << stats.output;
  EXPECT_NE(stats.output.find("## sink (5 objects)"), std::string::npos) << stats.output;
}

TEST(GenerateCli, BadArgumentsFailWithAMessage) {
  const fs::path dir = test::freshTempDir();
  const auto badCategory = runSagrid("generate --category oven --count 1 --out " + shellQuote(dir.string()));
  EXPECT_EQ(badCategory.exitCode, 2) << badCategory.output;
  const auto noCategory = runSagrid("generate --count 1 --out " + shellQuote(dir.string()));
  EXPECT_EQ(noCategory.exitCode, 1) << noCategory.output;
  EXPECT_NE(noCategory.output.find("--category is required"), std::string::npos) << noCategory.output;
}

TEST(GenerateCli, BenchPresetWritesTrainAndValSplitsSlow) {
  const fs::path dir = test::freshTempDir();
  const auto r = runSagrid("generate --preset bench --out " + shellQuote(dir.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(lineCount(dir / "train" / "manifest.jsonl"), 400);
  EXPECT_EQ(lineCount(dir / "val" / "manifest.jsonl"), 100);
  const std::string train = readFileBytes(dir / "train" / "manifest.jsonl");
  EXPECT_NE(train.find("\"id\":\"stove_s1001_00199\""), std::string::npos);
  EXPECT_NE(train.find("\"id\":\"sink_s1002_00199\""), std::string::npos);
}

}  // namespace
}  // namespace sagrid
