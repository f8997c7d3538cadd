// Copying a model's files into a models folder, including one made of links to the folder it is
// copied from (`scorer train --out M` where M links the shipped models: before, "internal error:
// cannot copy file: File exists").
#include "core/model/model_files.h"

#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "support/test_paths.h"

namespace sagrid::model {
namespace {
namespace fs = std::filesystem;

TEST(ModelFiles, CopiesAModelsFilesAndKeepsLinksToThemAsTheyAre) {
  const fs::path from = test::freshTempDir("model-files-from");
  writeFileAtomic(from / "stove.heatsource.json", "card");
  writeFileAtomic(from / "stove.heatsource.pt", "weights");
  writeFileAtomic(from / "sink.fluidsource.json", "other card");

  const fs::path copied = test::freshTempDir("model-files-copied");
  writeFileAtomic(copied / "stove.heatsource.pt", "older weights");
  copyModelFiles(from, copied, "stove.heatsource");
  EXPECT_EQ(readFileBytes(copied / "stove.heatsource.json"), "card");
  EXPECT_EQ(readFileBytes(copied / "stove.heatsource.pt"), "weights");  // replaced
  EXPECT_FALSE(fs::exists(copied / "sink.fluidsource.json"));           // another model's

  const fs::path linked = test::freshTempDir("model-files-linked");
  fs::create_symlink(from / "stove.heatsource.pt", linked / "stove.heatsource.pt");
  EXPECT_NO_THROW(copyModelFiles(from, linked));
  EXPECT_TRUE(fs::is_symlink(linked / "stove.heatsource.pt"));
  EXPECT_EQ(readFileBytes(linked / "stove.heatsource.pt"), "weights");
  EXPECT_EQ(readFileBytes(linked / "sink.fluidsource.json"), "other card");
}

}  // namespace
}  // namespace sagrid::model
