// Issue 14: hostile mesh files. Each crashed, hung, blew up memory or imported silently wrong
// before; now each is one FileError naming the file, decided before assimp parses anything.
#include "core/mesh/mesh_file_check.h"

#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/little_endian.h"
#include "core/mesh/mesh_import.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::writeFile;
using test::importError;

const fs::path kBad = fs::path(SAGRID_TEST_DATA_DIR) / "bad";

using io::put32;

// A GLB holding one triangle under `nodes` (glTF node objects, node 0 the scene root).
std::string triangleGlb(const nlohmann::json& nodes) {
  std::string bin;
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  bin.append(reinterpret_cast<const char*>(positions), sizeof positions);
  nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", nodes},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
         {"min", {0, 0, 0}}, {"max", {1, 1, 0}}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
      {"buffers", {{{"byteLength", 36}}}}};
  std::string json = gltf.dump();
  json.append((4 - json.size() % 4) % 4, ' ');
  std::string body;
  put32(body, static_cast<std::uint32_t>(json.size()));
  body += "JSON" + json;
  put32(body, static_cast<std::uint32_t>(bin.size()));
  body += std::string("BIN\0", 4) + bin;
  std::string out = "glTF";
  put32(out, 2);
  put32(out, static_cast<std::uint32_t>(12 + body.size()));
  return out + body;
}

// A 20 x 20 vertex grid as OBJ: all vertices, then 722 triangles, every line ended.
std::string gridObj() {
  std::string obj;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) obj += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
  for (int y = 0; y < 19; ++y) {
    for (int x = 0; x < 19; ++x) {
      const int a = y * 20 + x + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 21) + "\n";
      obj += "f " + std::to_string(a) + " " + std::to_string(a + 21) + " " + std::to_string(a + 20) + "\n";
    }
  }
  return obj;
}

TEST(MeshFileCheck, GlbNested20000DeepIsRefusedBeforeAssimpRecurses) {
  nlohmann::json nodes = nlohmann::json::array();
  for (int i = 0; i < 20000; ++i) nodes.push_back({{"children", {i + 1}}});
  nodes.push_back({{"mesh", 0}});
  const fs::path path = writeFile(test::freshTempDir() / "deep.glb", triangleGlb(nodes));
  EXPECT_THAT(importError(path), HasSubstr("nests its glTF nodes more than 256 levels deep"));
  // A reasonable hierarchy still imports, with every transform applied.
  nodes = nlohmann::json::array();
  for (int i = 0; i < 100; ++i) nodes.push_back({{"children", {i + 1}}, {"translation", {1, 0, 0}}});
  nodes.push_back({{"mesh", 0}});
  const Mesh mesh = importMesh(writeFile(test::freshTempDir() / "ok.glb", triangleGlb(nodes)));
  EXPECT_NEAR(mesh.bounds().min().x(), 100.0f, 1e-3f);
}

TEST(MeshFileCheck, GlbNodeCyclesAndSharedChildrenAreRefused) {
  const fs::path dir = test::freshTempDir();
  const nlohmann::json cycle = {{{"children", {1}}}, {{"children", {2}}, {"mesh", 0}}, {{"children", {1}}}};
  EXPECT_THAT(importError(writeFile(dir / "cycle.glb", triangleGlb(cycle))),
              HasSubstr("more than one parent"));
  const nlohmann::json loop = {{{"mesh", 0}}, {{"children", {2}}}, {{"children", {1}}}};
  EXPECT_THAT(importError(writeFile(dir / "loop.glb", triangleGlb(loop))), HasSubstr("a cycle"));
  const nlohmann::json missing = {{{"children", {7}}, {"mesh", 0}}};
  EXPECT_THAT(importError(writeFile(dir / "missing.glb", triangleGlb(missing))),
              HasSubstr("lists a child that does not exist"));
}

// It took 2.2 GB before; the chunk length is checked against the file's size.
TEST(MeshFileCheck, GlbChunkLengthBeyondTheFile) {
  EXPECT_THAT(importError(kBad / "glb_chunk_length_2_2gb.glb"),
              HasSubstr("JSON chunk declares 2200000000 bytes, more than the file holds"));
}

// Loaded as y-up glTF before; the content decides what it is.
TEST(MeshFileCheck, ContentMustMatchTheExtension) {
  EXPECT_THAT(importError(kBad / "obj_text_named.glb"),
              HasSubstr("holds OBJ text but is named .glb; rename it to .obj"));
  const fs::path dir = test::freshTempDir();
  EXPECT_THAT(importError(writeFile(dir / "mesh.obj", triangleGlb({{{"mesh", 0}}}))),
              HasSubstr("holds binary glTF (GLB) but is named .obj"));
  EXPECT_THAT(importError(writeFile(dir / "mesh.stl", "ply\nformat ascii 1.0\nend_header\n")),
              HasSubstr("holds PLY but is named .stl"));
  EXPECT_EQ(sniffMeshFormat("solid x\n facet normal 0 0 1\n"), "ASCII STL");
  EXPECT_EQ(sniffMeshFormat("<?xml version=\"1.0\"?>\n<COLLADA>"), "COLLADA XML");
  EXPECT_EQ(sniffMeshFormat("# made by hand\nv 0 0 0\n"), "OBJ text");
  EXPECT_EQ(sniffMeshFormat("hello"), "");
}

// assimp's ai_assert in TriangulateProcess aborted the process.
TEST(MeshFileCheck, AsciiPlyTruncatedHalfway) {
  EXPECT_THAT(importError(kBad / "ascii_truncated_half.ply"),
              HasSubstr("PLY declares 262 elements, one line each, but has only 148 lines of data"));
  // Every line there but one cut short: the same abort, caught line by line.
  std::string whole;
  {
    std::ifstream in(kBad / "ascii_truncated_half.ply", std::ios::binary);
    whole.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::size_t header = whole.find("end_header\n") + 11;
  std::string shortLine = whole.substr(0, header);
  shortLine.replace(shortLine.find("element vertex 100"), 18, "element vertex 3");
  shortLine.replace(shortLine.find("element face 162"), 16, "element face 1");
  shortLine += "0 0 0\n1 0 0\n0 1 0\n3 0 1\n";
  const fs::path path = writeFile(test::freshTempDir() / "short_line.ply", shortLine);
  EXPECT_THAT(importError(path), HasSubstr("face 0 (data line 4) has 3 values where 4 are declared"));
}

// assimp spun at 100 % CPU.
TEST(MeshFileCheck, BinaryPlyCutInItsHeader) {
  EXPECT_THAT(importError(kBad / "binary_cut_in_header.ply"),
              HasSubstr("PLY header has no end_header line"));
}

// 187 bytes took 663 MB.
TEST(MeshFileCheck, PlyCountsBeyondTheFileSize) {
  EXPECT_THAT(importError(kBad / "claims_10m_vertices.ply"),
              HasSubstr("declares 10000000 vertex elements but the file has only 187 bytes"));
  const fs::path dir = test::freshTempDir();
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 10000000\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  binary += std::string(36, '\0');
  EXPECT_THAT(importError(writeFile(dir / "binary.ply", binary)),
              HasSubstr("declares 10000000 vertex elements"));
  std::string lists =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n";
  lists += std::string(36, '\0') + std::string(1, char(200)) + std::string(12, '\0');
  EXPECT_THAT(importError(writeFile(dir / "lists.ply", lists)), HasSubstr("PLY ends inside face 0 (truncated?)"));
}

// Fuzz findings: a header whose "end_header" sits inside another line (assimp read past its
// data: SIGSEGV) and faces of 0 vertices or with indices past the vertex list (assimp's
// triangulation assert).
TEST(MeshFileCheck, PlyHeaderStatementsAndFacesAreChecked) {
  const fs::path dir = test::freshTempDir();
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_THAT(importError(writeFile(dir / "junk.ply", header + "ele=ment x\nend_header\n" + vertices + "3 0 1 2\n")),
              HasSubstr("PLY header line 9 is not a PLY statement"));
  EXPECT_THAT(importError(writeFile(dir / "inline.ply", header + "xend_headerx 1\n" + vertices + "3 0 1 2\n")),
              HasSubstr("PLY header has no end_header line"));
  EXPECT_THAT(importError(writeFile(dir / "empty_face.ply", header + "end_header\n" + vertices + "0\n")),
              HasSubstr("PLY face 0 lists 0 vertices"));
  EXPECT_THAT(importError(writeFile(dir / "index.ply", header + "end_header\n" + vertices + "3 0 1 7\n")),
              HasSubstr("PLY face 0 refers to vertex 7 of 3"));
  EXPECT_EQ(importMesh(writeFile(dir / "ok.ply", header + "end_header\n" + vertices + "3 0 1 2\n")).triangleCount(), 1u);
  for (const char* name : {"binary_reader_segv.ply", "binary_triangulate_assert.ply"})
    EXPECT_THAT(importError(kBad / "fuzz" / "mesh_ply" / name), HasSubstr("PLY "));
}

TEST(MeshFileCheck, BinaryStlCountBeyondTheFileSize) {
  std::string stl(80, ' ');
  put32(stl, 1000000);
  stl += std::string(50, '\0');
  const fs::path path = writeFile(test::freshTempDir() / "short.stl", stl);
  EXPECT_THAT(importError(path), HasSubstr("binary STL declares 1000000 triangles"));
}

TEST(MeshFileCheck, ColladaNestingIsBounded) {
  std::string dae = "<?xml version=\"1.0\"?>\n<COLLADA>";
  for (int i = 0; i < 5000; ++i) dae += "<node>";
  const fs::path path = writeFile(test::freshTempDir() / "deep.dae", dae);
  EXPECT_THAT(importError(path), HasSubstr("nests its XML elements more than 256 levels deep"));
}

// Imported 12 of 1,038 triangles without a word; now an error, or with lenient a warning.
TEST(MeshFileCheck, ObjTruncatedMidLineIsAnErrorUnlessLenient) {
  const std::string whole = gridObj();
  const fs::path dir = test::freshTempDir();
  const std::string cut = whole.substr(0, whole.size() * 3 / 4);
  ASSERT_NE(cut.back(), '\n');
  const fs::path path = writeFile(dir / "cut.obj", cut);
  EXPECT_THAT(importError(path), HasSubstr("is incomplete: it ends in the middle of a line"));
  ImportOptions lenient;
  lenient.lenient = true;
  const Mesh partial = importMesh(path, lenient);
  EXPECT_GT(partial.triangleCount(), 100u);
  EXPECT_LT(partial.triangleCount(), 722u);
  EXPECT_EQ(importMesh(writeFile(dir / "whole.obj", whole)).triangleCount(), 722u);
}

TEST(MeshFileCheck, ObjCoordinatesBeyondTheRange) {
  EXPECT_THAT(importError(kBad / "coordinates_1e30.obj"),
              HasSubstr("has coordinate 1e+30 at vertex 2; coordinates must be within +-1e9"));
}

TEST(MeshFileCheck, FifoAndDevicesAreRefusedAtOnce) {
  const fs::path fifo = test::freshTempDir() / "mesh.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THAT(importError(fifo), HasSubstr("is a FIFO (named pipe), not a regular file"));
  EXPECT_THAT(importError("/dev/zero"), HasSubstr("is a device"));
}

TEST(MeshFileCheck, SymlinkLoopAndLongNames) {
  const fs::path dir = test::freshTempDir();
  fs::create_symlink(dir / "b.obj", dir / "a.obj");
  fs::create_symlink(dir / "a.obj", dir / "b.obj");
  EXPECT_THAT(importError(dir / "a.obj"), HasSubstr("symbolic link loop"));
  EXPECT_THAT(importError(dir / (std::string(300, 'x') + ".obj")), HasSubstr("file name too long"));
}

// An OBJ's mtllib climbing out of its folder is not read (it would be copied on export).
TEST(MeshFileCheck, ReferencedFilesOutsideTheFolderAreNotRead) {
  const fs::path root = test::freshTempDir();
  fs::create_directories(root / "object");
  writeFile(root / "outside.mtl", "newmtl red\nKd 1 0 0\n");
  writeFile(root / "object" / "inside.mtl", "newmtl blue\nKd 0 0 1\n");
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const Mesh outside = importMesh(writeFile(root / "object" / "a.obj",
                                            "mtllib ../outside.mtl\n" + triangle + "usemtl red\nf 1 2 3\n"));
  for (const Material& m : outside.materials) EXPECT_NE(m.baseColor, Eigen::Vector3f(1, 0, 0));
  const Mesh inside = importMesh(writeFile(root / "object" / "b.obj",
                                           "mtllib inside.mtl\n" + triangle + "usemtl blue\nf 1 2 3\n"));
  ASSERT_FALSE(inside.materials.empty());
  bool blue = false;
  for (const Material& m : inside.materials) blue |= m.baseColor == Eigen::Vector3f(0, 0, 1);
  EXPECT_TRUE(blue);
}

}  // namespace
}  // namespace sagrid
