// Issue 14: a mesh import that takes too long is an error naming the file. Assimp is cancelled
// through its progress reports; where a loader ignores the cancel, the command line ends the
// process with the same one-line error (never in the GUI).
#include "core/mesh/import_time_limit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/mesh/mesh_import.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A flat grid of quads as OBJ text: enough work that assimp reports progress several times.
std::string gridObj(int n) {
  std::string text;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      text += "v " + std::to_string(i) + " " + std::to_string(j) + " 0\n";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j + 1;
      text += "f " + std::to_string(a) + " " + std::to_string(a + n + 1) + " " +
              std::to_string(a + 1) + "\n";
    }
  return text;
}

// Restores the process-wide limit after each test.
class ImportTimeLimitTest : public ::testing::Test {
 protected:
  void TearDown() override { setImportTimeLimit(m_saved); }
  ImportTimeLimit m_saved = importTimeLimit();
};

TEST_F(ImportTimeLimitTest, AnImportPastItsDeadlineIsCancelledWithAnErrorNamingTheFile) {
  const fs::path mesh = test::writeFile(test::freshTempDir() / "grid.obj", gridObj(60));
  setImportTimeLimit({1e-6, false});
  EXPECT_THAT(test::importError(mesh), HasSubstr("import did not finish within 1e-06 s"));
  setImportTimeLimit({60, false});
  EXPECT_EQ(importMesh(mesh).triangles.size(), 3600u);
  setImportTimeLimit({0, false});  // no limit
  EXPECT_EQ(importMesh(mesh).triangles.size(), 3600u);
}

TEST_F(ImportTimeLimitTest, NoLimitMeansNoProgressHandlerAndNeverExpired) {
  const ImportDeadline none("mesh.obj", {0, true});
  EXPECT_EQ(none.newProgressHandler(), nullptr);
  EXPECT_FALSE(none.expired());
}

// A loader that ignores the cancel (here: a scope that sleeps past the grace period).
TEST_F(ImportTimeLimitTest, ALoaderThatIgnoresTheCancelEndsTheCommandLineProcess) {
  EXPECT_EXIT(
      {
        const ImportDeadline deadline("stuck.ply", {0.05, true, 0.05});
        std::this_thread::sleep_for(std::chrono::seconds(10));
      },
      ::testing::ExitedWithCode(1),
      "sagrid: error: stuck.ply: import did not finish within 0.05 s");
  // Without exitProcess (the GUI) the same scope just ends late.
  const ImportDeadline gui("stuck.ply", {0.01, false, 0.01});
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_TRUE(gui.expired());
}

}  // namespace
}  // namespace sagrid
