#include "core/mesh/mesh_import.h"

#include <cstring>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::writeFile;
using test::importError;

const char* kTwoObjectsObj = R"(mtllib two.mtl
o first
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl red
f 1/1 2/2 3/3 4/4
o second
v 0 0 2
v 1 0 2
v 0 1 2
usemtl textured
f 5/1 6/2 7/4
)";

const char* kTwoMtl = R"(newmtl red
Kd 0.8 0.1 0.1
newmtl textured
Kd 1 1 1
map_Kd tex.ppm
)";

// A 2x1 binary PPM: left texel pure green, right texel pure blue.
const std::string kPpm = std::string("P6\n2 1\n255\n") + std::string("\x00\xff\x00\x00\x00\xff", 6);

TEST(MeshImport, ObjWithMtlTextureAndQuad) {
  const fs::path dir = test::freshTempDir();
  writeFile(dir / "two.mtl", kTwoMtl);
  writeFile(dir / "tex.ppm", kPpm);
  const fs::path obj = writeFile(dir / "two.obj", kTwoObjectsObj);
  const Mesh mesh = importMesh(obj);
  EXPECT_EQ(mesh.triangleCount(), 3u);  // quad triangulated + one triangle
  EXPECT_EQ(mesh.fileUp, UpAxis::Z);
  EXPECT_EQ(mesh.sha256, sha256Hex(readFileBytes(obj)));
  EXPECT_EQ(mesh.sha256.size(), 64u);
  const Eigen::AlignedBox3f box = mesh.bounds();
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector3f(0, 0, 0)));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector3f(1, 1, 2)));
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
  for (const auto& n : mesh.normals) EXPECT_NEAR(std::abs(n.z()), 1.0f, 1e-5f);
  ASSERT_EQ(mesh.triangleMaterials.size(), mesh.triangleCount());
  ASSERT_EQ(mesh.textures.size(), 1u);
  EXPECT_EQ(mesh.textures[0].width, 2);
  // Albedo of the red quad is the material colour; the textured triangle samples the PPM.
  int redTriangle = -1, texturedTriangle = -1;
  for (int t = 0; t < static_cast<int>(mesh.triangleCount()); ++t) {
    (mesh.positions[mesh.triangles[t][0]].z() > 1 ? texturedTriangle : redTriangle) = t;
  }
  EXPECT_TRUE(mesh.albedo(redTriangle, 0.3f, 0.3f).isApprox(Eigen::Vector3f(0.8f, 0.1f, 0.1f), 1e-5f));
  const Eigen::Vector3f texel = mesh.albedo(texturedTriangle, 0.25f, 0.5f);  // uv (0.25,0.5): left texel centre
  EXPECT_GT(texel.y(), 0.6f);
  EXPECT_LT(texel.x(), 0.1f);
}

TEST(MeshImport, MissingTextureFallsBackToMaterialColour) {
  const fs::path dir = test::freshTempDir();
  writeFile(dir / "two.mtl", kTwoMtl);  // tex.ppm is not there
  const Mesh mesh = importMesh(writeFile(dir / "two.obj", kTwoObjectsObj));
  EXPECT_TRUE(mesh.textures.empty());
  EXPECT_EQ(mesh.triangleCount(), 3u);
}

TEST(MeshImport, UpOverrideTurnsYUpFileToZUp) {
  const fs::path dir = test::freshTempDir();
  const fs::path obj = writeFile(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 2 0.5\nf 1 2 3\n");
  const Mesh zUp = importMesh(obj);
  const Mesh yUp = importMesh(obj, ImportOptions(UpAxis::Y));
  EXPECT_EQ(yUp.fileUp, UpAxis::Y);
  EXPECT_TRUE(zUp.positions[2].isApprox(Eigen::Vector3f(0, 2, 0.5f)));
  EXPECT_TRUE(yUp.positions[2].isApprox(Eigen::Vector3f(0, -0.5f, 2)));  // file y is up
  EXPECT_TRUE(zUpToFile(yUp.positions[2], UpAxis::Y).isApprox(Eigen::Vector3f(0, 2, 0.5f)));
  // Normals turn with the positions.
  const Eigen::Vector3f n = yUp.normals[0];
  const Eigen::Vector3f e = (yUp.positions[1] - yUp.positions[0]).cross(yUp.positions[2] - yUp.positions[0]).normalized();
  EXPECT_TRUE(n.isApprox(e, 1e-5f)) << n.transpose() << " vs " << e.transpose();
}

TEST(MeshImport, PlyWithVertexColoursAndStl) {
  const fs::path dir = test::freshTempDir();
  const fs::path ply = writeFile(dir / "c.ply", R"(ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
property uchar red
property uchar green
property uchar blue
element face 1
property list uchar int vertex_indices
end_header
0 0 0 255 0 0
1 0 0 0 255 0
0 1 0 0 0 255
3 0 1 2
)");
  const Mesh colored = importMesh(ply);
  ASSERT_EQ(colored.colors.size(), 3u);
  EXPECT_TRUE(colored.albedo(0, 0, 0).isApprox(Eigen::Vector3f(1, 0, 0), 1e-3f));
  EXPECT_TRUE(colored.albedo(0, 1, 0).isApprox(Eigen::Vector3f(0, 1, 0), 1e-3f));

  const fs::path stl = writeFile(dir / "t.STL", R"(solid t
facet normal 0 0 1
outer loop
vertex 0 0 0
vertex 2 0 0
vertex 0 3 0
endloop
endfacet
endsolid t
)");
  const Mesh tri = importMesh(stl);
  EXPECT_EQ(tri.triangleCount(), 1u);
  EXPECT_TRUE(tri.bounds().max().isApprox(Eigen::Vector3f(2, 3, 0)));
}

// ---- glTF / GLB built in memory: one triangle, a node transform, a material with a texture.

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned b0 = static_cast<unsigned char>(bytes[i]);
    const unsigned b1 = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
    const unsigned b2 = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0;
    out += table[b0 >> 2];
    out += table[((b0 & 3) << 4) | (b1 >> 4)];
    out += i + 1 < bytes.size() ? table[((b1 & 15) << 2) | (b2 >> 6)] : '=';
    out += i + 2 < bytes.size() ? table[b2 & 63] : '=';
  }
  return out;
}

// 2x2 PNG: red, green / blue, white.
const char* kPngBase64 =
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAEklEQVR4nGP4z8DAAMIM/4EAAB/uBfsL2WiLAAAAAElFTkSuQmCC";

std::string triangleBuffer() {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const float uvs[6] = {0.25f, 0.25f, 0.25f, 0.25f, 0.25f, 0.25f};  // glTF uv: top-left texel
  const std::uint16_t indices[4] = {0, 1, 2, 0};                  // padded to 4 bytes
  std::string bin(reinterpret_cast<const char*>(positions), sizeof(positions));
  bin.append(reinterpret_cast<const char*>(uvs), sizeof(uvs));
  bin.append(reinterpret_cast<const char*>(indices), sizeof(indices));
  return bin;
}

std::string gltfJson(const std::string& bufferUri, std::size_t bufferLength) {
  const std::string uri = bufferUri.empty() ? "" : "\"uri\": \"" + bufferUri + "\", ";
  return R"({"asset": {"version": "2.0"},
 "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"children": [1], "translation": [0, 0, 5]}, {"mesh": 0, "scale": [2, 2, 2]}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
 "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "baseColorTexture": {"index": 0}}}],
 "textures": [{"source": 0}],
 "images": [{"uri": "data:image/png;base64,)" + std::string(kPngBase64) + R"("}],
 "buffers": [{)" + uri + "\"byteLength\": " + std::to_string(bufferLength) + R"(}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                 {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                 {"buffer": 0, "byteOffset": 60, "byteLength": 6}],
 "accessors": [
  {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
  {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
  {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";
}

std::string glb() {
  std::string json = gltfJson("", triangleBuffer().size());
  while (json.size() % 4) json += ' ';
  const std::string bin = triangleBuffer();
  auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::uint32_t total = 12 + 8 + static_cast<std::uint32_t>(json.size()) + 8 +
                              static_cast<std::uint32_t>(bin.size());
  return "glTF" + u32(2) + u32(total) + u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json +
         u32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
}

void expectTransformedTriangle(const Mesh& mesh) {
  ASSERT_EQ(mesh.triangleCount(), 1u);
  EXPECT_EQ(mesh.fileUp, UpAxis::Y);
  // File frame: (0,0,5), (2,0,5), (0,2,5) after the node transforms; z-up: (x, -z, y).
  EXPECT_TRUE(mesh.bounds().min().isApprox(Eigen::Vector3f(0, -5, 0), 1e-5f)) << mesh.bounds().min().transpose();
  EXPECT_TRUE(mesh.bounds().max().isApprox(Eigen::Vector3f(2, -5, 2), 1e-5f)) << mesh.bounds().max().transpose();
  EXPECT_NEAR(std::abs(mesh.normals[0].y()), 1.0f, 1e-5f);  // file +z normal is now -y
  ASSERT_EQ(mesh.textures.size(), 1u);
  EXPECT_EQ(mesh.textures[0].width, 2);
  // Base colour 0.5 times the red texel.
  EXPECT_TRUE(mesh.albedo(0, 0.3f, 0.3f).isApprox(Eigen::Vector3f(0.5f, 0, 0), 1e-3f))
      << mesh.albedo(0, 0.3f, 0.3f).transpose();
}

TEST(MeshImport, GltfWithNodeTransformsEmbeddedTextureYUp) {
  const fs::path dir = test::freshTempDir();
  const std::string bin = triangleBuffer();
  const fs::path gltf = writeFile(
      dir / "tri.gltf", gltfJson("data:application/octet-stream;base64," + base64(bin), bin.size()));
  expectTransformedTriangle(importMesh(gltf));
}

TEST(MeshImport, GlbWithNodeTransformsEmbeddedTextureYUp) {
  const fs::path dir = test::freshTempDir();
  const fs::path path = writeFile(dir / "tri.glb", glb());
  const Mesh mesh = importMesh(path);
  expectTransformedTriangle(mesh);
  // --up z keeps the file's numbers.
  const Mesh asZ = importMesh(path, ImportOptions(UpAxis::Z));
  EXPECT_TRUE(asZ.bounds().max().isApprox(Eigen::Vector3f(2, 2, 5), 1e-5f));
}

TEST(MeshImport, RealDevObjectsImport) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP();
  for (const char* name : {"libero__basin_faucet", "libero__faucet_knob", "libero__flat_stove"}) {
    const Mesh mesh = importMesh(test::realDevDir() / name / "mesh.obj");
    EXPECT_GT(mesh.triangleCount(), 1000u) << name;
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_FALSE(mesh.materials.empty());
    const Eigen::Vector3f extent = mesh.bounds().sizes();
    EXPECT_GT(extent.maxCoeff(), 0.05f) << name;  // metres: centimetre-to-metre sized objects
    EXPECT_LT(extent.maxCoeff(), 2.0f) << name;
  }
}

// ---- Bad input: one line, naming the file and the problem.

TEST(MeshImportErrors, MissingDirectoryExtensionEmpty) {
  const fs::path dir = test::freshTempDir();
  EXPECT_THAT(importError(dir / "none.obj"), HasSubstr("file not found"));
  fs::create_directory(dir / "folder.obj");
  EXPECT_THAT(importError(dir / "folder.obj"), HasSubstr("is a directory"));
  EXPECT_THAT(importError(writeFile(dir / "mesh.xyz", "v 0 0 0\n")),
              HasSubstr("unsupported mesh format '.xyz'"));
  EXPECT_THAT(importError(writeFile(dir / "noext", "v 0 0 0\n")), HasSubstr("unsupported mesh format"));
  EXPECT_THAT(importError(writeFile(dir / "empty.glb", "")), HasSubstr("is empty (0 bytes)"));
  EXPECT_THAT(importError(writeFile(dir / "empty.obj", "")), HasSubstr("is empty"));
}

TEST(MeshImportErrors, TruncatedAndCorruptGlb) {
  const fs::path dir = test::freshTempDir();
  const std::string whole = glb();
  // Checked before assimp sees them (mesh_file_check).
  EXPECT_THAT(importError(writeFile(dir / "half.glb", whole.substr(0, whole.size() / 2))),
              HasSubstr("(truncated?)"));
  EXPECT_THAT(importError(writeFile(dir / "header.glb", whole.substr(0, 10))),
              HasSubstr("binary glTF is truncated (10 bytes)"));
  EXPECT_THAT(importError(writeFile(dir / "junk.glb", std::string(200, 'x'))),
              HasSubstr("is not a binary glTF file"));
}

// Binary STL with one facet; text parsers read "nan" as 0, binary files carry real NaN bits.
std::string binaryStl(float x) {
  std::string bytes(80, ' ');
  const std::uint32_t count = 1;
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  const float facet[12] = {0, 0, 1, 0, 0, 0, x, 0, 0, 0, 1, 0};
  bytes.append(reinterpret_cast<const char*>(facet), sizeof(facet));
  bytes.append(2, '\0');
  return bytes;
}

TEST(MeshImportErrors, NanAndInfVertices) {
  const fs::path dir = test::freshTempDir();
  EXPECT_EQ(importMesh(writeFile(dir / "ok.stl", binaryStl(1.0f))).triangleCount(), 1u);
  EXPECT_THAT(importError(writeFile(dir / "nan.stl", binaryStl(std::numeric_limits<float>::quiet_NaN()))),
              HasSubstr("NaN or infinite coordinates (vertex 2)"));
  EXPECT_THAT(importError(writeFile(dir / "inf.stl", binaryStl(std::numeric_limits<float>::infinity()))),
              HasSubstr("NaN or infinite"));
  EXPECT_THAT(importError(writeFile(dir / "huge.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n")),
              ::testing::AnyOf(HasSubstr("NaN or infinite"), HasSubstr("not finite")));
}

TEST(MeshImportErrors, OnlyDegenerateTriangles) {
  const fs::path dir = test::freshTempDir();
  EXPECT_THAT(importError(writeFile(dir / "line.obj",
                                    "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 4 4 4\n")),
              HasSubstr("only degenerate triangles"));
}

TEST(MeshImport, TwoVertexFacesAmongTrianglesAreLeftOut) {
  // Some Sweet Home 3D models (Kator Legaz's coffee maker) hold "f a b" faces among their
  // triangles; assimp's validator refused the whole file ("is a LINE but mPrimitiveTypes does not
  // report the LINE flag"). The lines are dropped; the triangles stay.
  const fs::path dir = test::freshTempDir();
  const Mesh mesh = importMesh(writeFile(dir / "with_line.obj",
                                         "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                                         "f 1 2 3\nf 1 3 4\nf 4 5\nf 1 2 5\nl 2 5\n"));
  EXPECT_EQ(mesh.triangles.size(), 3u);
  // Only lines: still no triangles, said as such.
  EXPECT_THAT(
      importError(writeFile(dir / "only_lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\nf 2 3\n")),
      HasSubstr("no triangles"));
}

TEST(MeshImport, PolygonsTheTriangulationCannotFullySplitAreNotACutFile) {
  // The door-handle profile of Sweet Home 3D's fridge: one flat 32-gon, a row of collinear points
  // under an arc. Assimp's ear clipping makes 28 of its 30 triangles; the file is whole, so it is
  // read (a warning says what was lost) rather than refused as truncated.
  const float xz[] = {0,       0.306f, -0.075f, 0.306f, -0.15f,  0.306f, -0.225f, 0.306f,
                      -0.3f,   0.306f, -0.3f,   0.313f, -0.299f, 0.318f, -0.297f, 0.323f,
                      -0.289f, 0.326f, -0.272f, 0.33f,  -0.242f, 0.334f, -0.2f,   0.338f,
                      -0.15f,  0.341f, -0.1f,   0.343f, -0.056f, 0.345f, -0.025f, 0.346f,
                      0,       0.346f, 0.025f,  0.345f, 0.057f,  0.344f, 0.1f,    0.343f,
                      0.15f,   0.341f, 0.2f,    0.338f, 0.243f,  0.334f, 0.272f,  0.33f,
                      0.29f,   0.326f, 0.297f,  0.323f, 0.299f,  0.318f, 0.3f,    0.313f,
                      0.3f,    0.306f, 0.225f,  0.306f, 0.15f,   0.306f, 0.075f,  0.306f};
  std::string obj, face = "f";
  for (int v = 0; v < 32; ++v) {
    obj += "v " + std::to_string(xz[2 * v]) + " 0 " + std::to_string(xz[2 * v + 1]) + "\n";
    face += " " + std::to_string(v + 1);
  }
  const fs::path dir = test::freshTempDir();
  const Mesh mesh = importMesh(writeFile(dir / "handle.obj", obj + face + "\n"));
  EXPECT_GT(mesh.triangles.size(), 20u);
  EXPECT_LE(mesh.triangles.size(), 30u);
  // A file cut after its faces were declared is still refused.
  EXPECT_THAT(importError(writeFile(dir / "cut.obj", obj + face + "\nf 1 2 3\nf 4 5")),
              HasSubstr("incomplete"));
}

TEST(MeshImportErrors, EmptyScene) {
  const fs::path dir = test::freshTempDir();
  EXPECT_THAT(importError(writeFile(dir / "points.obj", "# just vertices\nv 0 0 0\nv 1 0 0\n")),
              HasSubstr("no triangles"));
  EXPECT_THAT(importError(writeFile(dir / "comment.obj", "# nothing here\n")), HasSubstr(": "));
  EXPECT_THAT(importError(writeFile(dir / "nofaces.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                                    "property float y\nproperty float z\nend_header\n")),
              HasSubstr(": "));
}

TEST(MeshImport, CoordinatesOf1e9) {
  const fs::path dir = test::freshTempDir();
  // Huge but well-scaled: imported, and it normalizes to the unit cube.
  const Mesh big = importMesh(writeFile(dir / "big.obj", "v -1e9 0 0\nv 1e9 0 0\nv 0 1e9 0\nf 1 2 3\n"));
  EXPECT_FLOAT_EQ(big.bounds().sizes().x(), 2e9f);
  // A small object far from the origin: float cannot hold its shape, so it is refused.
  EXPECT_THAT(importError(writeFile(dir / "far.obj", "v 1e9 0 0\nv 1e9 0.5 0\nv 1e9 0 0.5\nf 1 2 3\n")),
              HasSubstr("too small"));
}

TEST(MeshImport, UpAxisStrings) {
  EXPECT_EQ(parseUpAxis("y"), UpAxis::Y);
  EXPECT_EQ(parseUpAxis("Z"), UpAxis::Z);
  EXPECT_EQ(parseUpAxis("x"), UpAxis::PosX);
  EXPECT_EQ(parseUpAxis("+x"), UpAxis::PosX);
  EXPECT_EQ(parseUpAxis("-Y"), UpAxis::NegY);
  EXPECT_EQ(parseUpAxis("-z"), UpAxis::NegZ);
  EXPECT_FALSE(parseUpAxis("w").has_value());
  EXPECT_FALSE(parseUpAxis("--x").has_value());
  for (UpAxis up : kAllUpAxes) EXPECT_EQ(parseUpAxis(toString(up)), up);
  EXPECT_STREQ(toString(UpAxis::Y), "y");
}

}  // namespace
}  // namespace sagrid

namespace sagrid {
namespace {

// Fuzzing found assimp's ASCII STL error quoting the rest of the file (45 KB, any bytes) and our
// one-line cleanup taking quadratic time over it (a fuzzer timeout). The reason is now one short
// line of printable ASCII, made in one pass.
TEST(MeshImport, AssimpErrorsBecomeOneShortPrintableLine) {
  std::string stl = "solid s\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n";
  for (int i = 0; i < 20000; ++i) stl += "   vertex  \x01\xff  x  y\n";
  const fs::path path = test::writeFile(test::freshTempDir() / "quoted.stl", stl);
  const std::string message = test::importError(path);
  EXPECT_LT(message.size(), path.string().size() + 400) << message.substr(0, 500);
  EXPECT_THAT(message, ::testing::HasSubstr("cannot be read as stl"));
  for (const unsigned char c : message) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << int(c);
}

}  // namespace
}  // namespace sagrid
