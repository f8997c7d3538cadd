// End-to-end: `sagrid corpus sweethome3d` on a small .sh3f built in the test (no Debian package
// needed): datasets written and readable, one summary line, and a clear failure that leaves
// nothing behind.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/dataset/dataset.h"
#include "support/sweethome3d_fixture.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::runSagrid;
using test::shellQuote;
using ::testing::HasSubstr;

TEST(CorpusCommand, SweetHome3dFromExplicitLibrary) {
  const fs::path dir = test::freshTempDir("corpus_cli");
  const auto f = test::writeSweetHome3dFixture(dir / "in");
  fs::create_directories(dir / "labels");
  const fs::path out = dir / "out";
  const auto r =
      runSagrid("corpus sweethome3d --out " + shellQuote(out.string()) + " --sh3f " +
                shellQuote(f.sh3f.string()) + " --labels " + shellQuote((dir / "labels").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("corpus: 4 objects"));
  EXPECT_THAT(r.output, HasSubstr("stove 2, sink 1, none 1"));
  EXPECT_THAT(r.output, HasSubstr("distractors 1, unlabelled 3"));
  EXPECT_THAT(r.output, HasSubstr("warning: test_lib_sink: refused reference '../shared.mtl'"));
  const auto unlabelled = readDataset(out / "unlabelled");
  ASSERT_EQ(unlabelled.size(), 3u);
  EXPECT_EQ(readFileBytes(unlabelled[0].mesh), f.cookerObj);
  const auto corpus = nlohmann::json::parse(readFileBytes(out / "corpus.json"));
  EXPECT_EQ(corpus["counts_by_role"]["none"], 1);
}

TEST(CorpusCommand, BadArchiveGivesOneClearErrorAndWritesNothing) {
  const fs::path dir = test::freshTempDir("corpus_cli_bad");
  writeFileAtomic(dir / "broken.sh3f", "this is not a zip");
  const fs::path out = dir / "out";
  const auto r = runSagrid("corpus sweethome3d --out " + shellQuote(out.string()) + " --sh3f " +
                           shellQuote((dir / "broken.sh3f").string()));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_THAT(r.output, HasSubstr("broken.sh3f: is not a zip archive"));
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace sagrid
