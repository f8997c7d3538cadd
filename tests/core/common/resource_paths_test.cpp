// Resource lookup: the working directory's resources/, the installed share/sagrid beside the
// binary, the source tree; first existing folder wins, the installed path is named otherwise.
#include "core/common/resource_paths.h"

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;

TEST(ResourcePaths, FirstRootHoldingTheFolderWins) {
  const fs::path dir = test::freshTempDir();
  const fs::path cwd = dir / "cwd", installed = dir / "share", source = dir / "src";
  fs::create_directories(installed / "models");
  fs::create_directories(source / "models");
  fs::create_directories(source / "samples");
  const std::vector<fs::path> roots{cwd, installed, source};
  EXPECT_EQ(findResourceDir("models", roots), installed / "models");
  EXPECT_EQ(findResourceDir("samples", roots), source / "samples");
  fs::create_directories(cwd / "models");
  EXPECT_EQ(findResourceDir("models", roots), cwd / "models");
}

TEST(ResourcePaths, MissingFolderNamesTheInstalledLocation) {
  const fs::path dir = test::freshTempDir();
  EXPECT_EQ(findResourceDir("models", {dir / "a", dir / "b", dir / "c"}), dir / "b" / "models");
}

TEST(ResourcePaths, InstalledRootIsShareSagridBesideTheBinary) {
  const auto roots = resourceRoots();
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_EQ(roots[0], fs::path("resources"));
  EXPECT_EQ(roots[1], (executableDir() / ".." / "share" / "sagrid").lexically_normal());
  EXPECT_EQ(roots[2], fs::path(SAGRID_SOURCE_DIR) / "resources");
  EXPECT_TRUE(fs::exists(executableDir() / "test_core_common")) << executableDir();
}

TEST(ResourcePaths, DefaultModelsFoundFromTheBuildTree) {
  EXPECT_TRUE(fs::is_directory(defaultModelsDir())) << defaultModelsDir();
  EXPECT_TRUE(fs::exists(defaultModelsDir() / "stove.heatsource.json"));
}

}  // namespace
}  // namespace sagrid
