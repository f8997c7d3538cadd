// sagrid units memory from the command line (issue 41 item 5): the leave-one-source-out table is
// printed, and the memory is written only where it beats the named units; a folder that is not
// there, or one with no curated object, is one clear error and nothing is written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/annotate/size_memory.h"
#include "core/generate/dataset_generator.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::quotedPath;
using test::runSagrid;
using ::testing::HasSubstr;

TEST(UnitsCli, OneSourceCannotBeatTheNamedUnitsSoNothingIsWritten) {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 1, 81}, {"sink", 1, 82}}, gen::MeshFormat::Obj, dir / "one-source");
  // Left out by source, a single source leaves the memory empty: the named units decide alone.
  auto r = runSagrid("units memory --data " + quotedPath(dir / "one-source") + " --out " +
                     quotedPath(dir / "out") + " --report " + quotedPath(dir / "report"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("| named units only (no memory) |"));
  EXPECT_THAT(r.output, HasSubstr("units memory refused"));
  EXPECT_THAT(r.output, HasSubstr("nothing written"));
  EXPECT_FALSE(fs::exists(dir / "out" / kSizeMemoryFile));
  EXPECT_TRUE(fs::exists(dir / "report" / "units_memory.md"));

  r = runSagrid("units memory --data " + quotedPath(dir / "gone") + " --out " + quotedPath(dir / "out"));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_THAT(r.output, HasSubstr((dir / "gone").string()));
  fs::create_directories(dir / "empty");
  r = runSagrid("units memory --data " + quotedPath(dir / "empty") + " --out " + quotedPath(dir / "out"));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_THAT(r.output, HasSubstr("no curated objects"));
  EXPECT_FALSE(fs::exists(dir / "out" / kSizeMemoryFile));
  // Growing a memory needs one there; one of nothing needs --data or --into.
  r = runSagrid("units memory --into " + quotedPath(dir / "empty"));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_THAT(r.output, HasSubstr("no units_memory.json there"));
  r = runSagrid("units memory --data " + quotedPath(dir / "one-source") + " --measures height,width");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_THAT(r.output, HasSubstr("unknown size measure 'width'"));
  r = runSagrid("units memory --out " + quotedPath(dir / "out"));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_THAT(r.output, HasSubstr("needs --data DIR, --into MODELS or both"));
}

}  // namespace
}  // namespace sagrid
