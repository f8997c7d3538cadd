#include "core/annotate/object_list.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST(ObjectList, RoundTripsIdsAndAbsolutePaths) {
  const fs::path dir = test::freshTempDir();
  writeObjectList(dir / "list.txt", {{dir / "a" / "mesh.glb", "a"}, {"rel/chair.obj", "chair 2"}});
  const auto files = readObjectList(dir / "list.txt");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].id, "a");
  EXPECT_EQ(files[0].path, dir / "a" / "mesh.glb");
  EXPECT_EQ(files[1].id, "chair 2");
  EXPECT_EQ(files[1].path, fs::absolute("rel/chair.obj").lexically_normal());
}

TEST(ObjectList, ReadsBarePathsRelativeToTheListAndSkipsComments) {
  const fs::path dir = test::freshTempDir();
  std::ofstream(dir / "l.list") << "# candidates\n\nstove1/mesh.glb\r\nsinks/s2.obj\n";
  const auto files = listObjects(dir / "l.list");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].id, "stove1");
  EXPECT_EQ(files[0].path, dir / "stove1" / "mesh.glb");
  EXPECT_EQ(files[1].id, "s2");
  EXPECT_TRUE(isObjectListFile("x.txt"));
  EXPECT_FALSE(isObjectListFile("x.obj"));
}

TEST(ObjectList, NamesTheFileAndLineOfABadEntry) {
  const fs::path dir = test::freshTempDir();
  std::ofstream(dir / "dup.txt") << "a/mesh.obj\nb/a.obj\n";
  try {
    readObjectList(dir / "dup.txt");
    ADD_FAILURE() << "duplicate id accepted";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("dup.txt: line 2: object id 'a' is listed twice"));
  }
  std::ofstream(dir / "empty-id.txt") << "\tx.obj\n";
  EXPECT_THROW(readObjectList(dir / "empty-id.txt"), FileError);
  std::ofstream(dir / "escape.txt") << "../x\tx.obj\n";
  try {
    readObjectList(dir / "escape.txt");
    ADD_FAILURE() << "id with a path separator accepted";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("line 1: object id '../x'"));
  }
  EXPECT_THROW(readObjectList(dir / "missing.txt"), FileError);
}

}  // namespace
}  // namespace sagrid
