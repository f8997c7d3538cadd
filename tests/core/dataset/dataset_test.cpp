#include "core/dataset/dataset.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "core/mesh/mesh_import.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST(Dataset, ReadsTheManifest) {
  const fs::path dir = test::freshTempDir();
  std::ofstream(dir / "manifest.jsonl")
      << R"({"id":"a","category":"stove","mesh":"a/mesh.obj","labels":"a/labels.json"})"
      << "\n\n"
      << R"({"id":"b","category":"sink","mesh":"b/mesh.glb"})"
      << "\n";
  const auto entries = readDataset(dir);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].category, "stove");
  EXPECT_EQ(entries[0].mesh, dir / "a/mesh.obj");
  EXPECT_EQ(entries[1].labels, dir / "b/labels.json");
}

TEST(Dataset, MalformedManifestLinesNameTheLine) {
  const fs::path dir = test::freshTempDir();
  std::ofstream(dir / "manifest.jsonl") << R"({"id":"a","mesh":"a/mesh.obj"})"
                                        << "\n{oops\n";
  try {
    readDataset(dir);
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("line 2"));
  }
  EXPECT_THROW(readDataset(dir / "missing"), FileError);
}

TEST(Dataset, EmptyFolderIsAnEmptyDatasetAndMeshFilesGoByExtension) {
  const fs::path empty = test::freshTempDir();
  EXPECT_TRUE(readDataset(empty).empty());
  EXPECT_TRUE(isMeshFile("x/Model.GLB"));
  EXPECT_FALSE(isMeshFile("x/labels.json"));
}

TEST(Dataset, WithoutAManifestScansObjectFoldersLikeRealDev) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP() << "no " << test::realDevDir();
  const auto entries = readDataset(test::realDevDir());
  ASSERT_EQ(entries.size(), 3u);
  for (const auto& e : entries) {
    EXPECT_EQ(e.mesh.filename(), "mesh.obj");
    EXPECT_FALSE(e.category.empty());
  }
}

}  // namespace
}  // namespace sagrid
