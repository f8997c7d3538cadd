// Issue 14: every importing subcommand answers each damaged mesh of the bad-input corpus with
// exit 1 and a line naming the file and the problem, in seconds; before, these crashed
// (stack overflow, abort), hung (FIFO, binary PLY cut in its header), took gigabytes, or exited 0.
// `timeout` turns a hang into a failure instead of a stuck test run.
#include <sys/stat.h>

#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/fbx_files.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::shellQuote;

const fs::path kBad = fs::path(SAGRID_TEST_DATA_DIR) / "bad";

struct BadMesh {
  fs::path path;
  std::string problem;  // a fragment of the message
};

// The damaged meshes: the small ones from tests/data/bad, the big or special ones made here.
std::vector<BadMesh> badMeshes(const fs::path& dir) {
  std::string deep = "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[";
  for (int i = 0; i < 20000; ++i) deep += "{\"children\":[" + std::to_string(i + 1) + "]},";
  deep += "{}]}";
  std::ofstream(dir / "deep.gltf") << deep;
  std::ofstream(dir / "deep.fbx") << test::nestedAsciiFbx(20000);
  ::mkfifo((dir / "fifo.obj").c_str(), 0600);
  return {{kBad / "ascii_truncated_half.ply", "(truncated?)"},
          {kBad / "binary_cut_in_header.ply", "no end_header"},
          {kBad / "claims_10m_vertices.ply", "declares 10000000 vertex elements"},
          {kBad / "obj_text_named.glb", "holds OBJ text but is named .glb"},
          {kBad / "glb_chunk_length_2_2gb.glb", "more than the file holds"},
          {kBad / "coordinates_1e30.obj", "coordinates must be within"},
          {dir / "deep.gltf", "nests its glTF nodes more than 256 levels deep"},
          {dir / "deep.fbx", "nests its FBX models more than 256 levels deep"},
          {dir / "fifo.obj", "is a FIFO"},
          {"/dev/zero", "is a device, not a regular file"}};
}

// Runs `sagrid <command with {} replaced by the mesh>` and checks the answer.
void expectClearError(const std::string& command, const BadMesh& bad) {
  std::string line = command;
  line.replace(line.find("{}"), 2, shellQuote(bad.path.string()));
  const auto r = test::runCommand("timeout 60 " + shellQuote(test::sagridBinary().string()) + " " + line);
  EXPECT_EQ(r.exitCode, 1) << line << "\n" << r.output;
  EXPECT_THAT(r.output, HasSubstr(bad.path.string() + ": ")) << line;
  EXPECT_THAT(r.output, HasSubstr(bad.problem)) << line;
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("internal error"))) << line;
}

TEST(HostileInputCliSlow, EveryImportingCommandAnswersEveryDamagedMesh) {
  const fs::path dir = test::freshTempDir();
  const std::string out = shellQuote((dir / "out").string());
  const std::string models = shellQuote((fs::path(SAGRID_SOURCE_DIR) / "resources" / "models").string());
  for (const BadMesh& bad : badMeshes(dir)) {
    expectClearError("info {}", bad);
    expectClearError("voxelize {} --out " + shellQuote((dir / "v.npz").string()), bad);
    expectClearError("extract {} --out " + out, bad);
    expectClearError("up-axis {}", bad);
    expectClearError("annotate {} --symmetries 1 --models " + models + " --out " + out, bad);
  }
}

// Only the one error line: no duplicate from the log, nothing else.
TEST(HostileInputCli, InfoSaysItOnOneLine) {
  const fs::path dir = test::freshTempDir();
  for (const BadMesh& bad : badMeshes(dir)) {
    const auto r = test::runSagrid("info " + shellQuote(bad.path.string()));
    EXPECT_EQ(r.output.rfind("sagrid: error: " + bad.path.string() + ": ", 0), 0u) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}

// --lenient is a global option and may follow the subcommand.
TEST(HostileInputCli, LenientReadsATruncatedObjWithAWarning) {
  const fs::path dir = test::freshTempDir();
  std::ofstream(dir / "cut.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\nf 1 2";
  const std::string mesh = shellQuote((dir / "cut.obj").string());
  auto r = test::runSagrid("info " + mesh);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_THAT(r.output, HasSubstr("is incomplete: it ends in the middle of a line"));
  r = test::runSagrid("info --lenient " + mesh);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("incomplete file (--lenient): it ends in the middle of a line; "
                                  "read 2 triangles"));
  EXPECT_EQ(test::runSagrid("--lenient info " + mesh).exitCode, 0);
}

// --import-time-limit (a root option, default 120 s) bounds every import with one clear line.
TEST(HostileInputCli, ImportTimeLimitIsOneClearLine) {
  const fs::path mesh = test::freshTempDir() / "quad.obj";
  std::ofstream(mesh) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
  const auto r = test::runSagrid("info " + shellQuote(mesh.string()) + " --import-time-limit 1e-9");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(r.output, "sagrid: error: " + mesh.string() +
                          ": import did not finish within 1e-09 s (--import-time-limit); the file "
                          "may be malformed or too large\n");
  EXPECT_EQ(test::runSagrid("info " + shellQuote(mesh.string()) + " --import-time-limit 0").exitCode, 0);
  EXPECT_EQ(test::runSagrid("info " + shellQuote(mesh.string()) + " --import-time-limit -1").exitCode, 2);
}

// A Latin-1 folder name (not UTF-8) made extract and annotate stop with "internal error" (the
// path could not be written as JSON); now the id is "caf_" and the run completes.
TEST(HostileInputCli, NonUtf8FileNamesWork) {
  const fs::path dir = test::freshTempDir();
  const fs::path object = dir / "in" / "caf\xE9";
  fs::create_directories(object);
  const fs::path sample = fs::path(SAGRID_SOURCE_DIR) / "resources" / "samples" / "stove_s42_00001";
  for (const char* name : {"mesh.obj", "mesh.mtl"}) fs::copy_file(sample / name, object / name);
  const std::string in = shellQuote((dir / "in").string());
  auto r = test::runSagrid("extract " + in + " --out " + shellQuote((dir / "features").string()));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "features" / "caf_.npz"));
  r = test::runSagrid("annotate " + in + " --symmetries 1 --models " +
                      shellQuote((fs::path(SAGRID_SOURCE_DIR) / "resources" / "models").string()) +
                      " --out " + shellQuote((dir / "labels").string()));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "labels" / "caf_" / "labels.json"));
}

}  // namespace
}  // namespace sagrid
