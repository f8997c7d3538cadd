// Object ids from file names (issue 14): they become folder names and JSON strings, so they are
// valid UTF-8 and bounded in length whatever the names on disk.
#include "core/mesh/mesh_files.h"

#include <algorithm>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "core/common/utf8.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

void touch(const fs::path& path) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << "v 0 0 0\n";
}

TEST(MeshFiles, IdsOfNonUtf8AndLongNamesAreUsable) {
  const fs::path dir = test::freshTempDir();
  touch(dir / "caf\xE9" / "mesh.obj");              // Latin-1, not UTF-8
  touch(dir / "d\xC3\xA9j\xC3\xA0" / "mesh.obj");  // UTF-8 kept as it is
  const std::string part(200, 'x');
  touch(dir / part / part / "mesh.obj");           // id "xxx...__xxx..." of 402 bytes
  const auto files = findMeshFiles(dir);
  ASSERT_EQ(files.size(), 3u);
  std::set<std::string> ids;
  for (const auto& f : files) {
    EXPECT_FALSE(firstInvalidUtf8(f.id)) << f.id;
    EXPECT_LE(f.id.size(), kMaxIdLength);
    ids.insert(f.id);
  }
  EXPECT_TRUE(ids.count("caf_"));
  EXPECT_TRUE(ids.count("d\xC3\xA9j\xC3\xA0"));
  const auto longId = std::find_if(files.begin(), files.end(), [](const MeshFile& f) {
    return f.id.size() == kMaxIdLength;
  });
  ASSERT_NE(longId, files.end());
  EXPECT_EQ(longId->id.substr(0, 10), "xxxxxxxxxx");
  EXPECT_EQ(findMeshFiles(dir / "caf\xE9" / "mesh.obj").front().id, "caf_");
}

}  // namespace
}  // namespace sagrid
