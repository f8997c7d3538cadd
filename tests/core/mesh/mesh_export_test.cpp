#include "core/mesh/mesh_export.h"

#include <cstring>

#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/mesh/mesh_import.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

// A textured quad and a coloured triangle, two materials.
Mesh sampleMesh(UpAxis up) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 3}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {0, 0}, {0, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
  m.triangleMaterials = {0, 0, 1};
  Texture t;
  t.width = 2;
  t.height = 2;
  t.rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  m.textures.push_back(t);
  m.materials.push_back({"glass", {1, 1, 1}, 0});
  m.materials.push_back({"red", {0.8f, 0.1f, 0.1f}, -1});
  m.fileUp = up;
  m.computeVertexNormals();
  return m;
}

TEST(MeshExport, ObjRoundTripsThroughImporter) {
  const auto dir = test::freshTempDir();
  const Mesh mesh = sampleMesh(UpAxis::Z);
  exportMesh(mesh, dir / "mesh.obj");
  ASSERT_TRUE(std::filesystem::exists(dir / "mesh.mtl"));
  ASSERT_TRUE(std::filesystem::exists(dir / "mesh_tex0.png"));
  const Mesh back = importMesh(dir / "mesh.obj");
  EXPECT_EQ(back.triangleCount(), 3u);
  EXPECT_TRUE(back.bounds().min().isApprox(mesh.bounds().min(), 1e-5f));
  EXPECT_TRUE(back.bounds().max().isApprox(mesh.bounds().max(), 1e-5f));
  ASSERT_EQ(back.textures.size(), 1u);
  EXPECT_EQ(back.textures[0].width, 2);
}

TEST(MeshExport, GlbIsYUpAndRoundTripsToTheSameZUpMesh) {
  const auto dir = test::freshTempDir();
  const Mesh mesh = sampleMesh(UpAxis::Y);
  const std::string glb = encodeGlb(mesh);
  ASSERT_GE(glb.size(), 20u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  std::uint32_t total = 0;
  std::memcpy(&total, glb.data() + 8, 4);
  EXPECT_EQ(total, glb.size());
  EXPECT_EQ(glb.size() % 4, 0u);
  writeFileAtomic(dir / "mesh.glb", glb);
  const Mesh back = importMesh(dir / "mesh.glb");
  EXPECT_EQ(back.fileUp, UpAxis::Y);
  EXPECT_EQ(back.triangleCount(), 3u);
  // The importer turns the y-up file back to z-up: same bounds as the mesh we wrote.
  EXPECT_TRUE(back.bounds().min().isApprox(mesh.bounds().min(), 1e-5f));
  EXPECT_TRUE(back.bounds().max().isApprox(mesh.bounds().max(), 1e-5f));
  ASSERT_EQ(back.textures.size(), 1u);
}

TEST(MeshExport, EncodingIsDeterministic) {
  const Mesh mesh = sampleMesh(UpAxis::Z);
  EXPECT_EQ(encodeGlb(mesh), encodeGlb(mesh));
  EXPECT_EQ(encodeObj(mesh, "m").files, encodeObj(mesh, "m").files);
  const std::string obj = encodeObj(mesh, "m").mainBytes();
  EXPECT_NE(obj.find("mtllib m.mtl"), std::string::npos);
  EXPECT_NE(obj.find("usemtl red"), std::string::npos);
  EXPECT_NE(obj.find("v 0 1 3\n"), std::string::npos);
}

TEST(MeshExport, VertexColoursAreWritten) {
  Mesh mesh = sampleMesh(UpAxis::Z);
  mesh.colors.assign(mesh.positions.size(), Eigen::Vector3f(0.5f, 0.25f, 1));
  const std::string obj = encodeObj(mesh, "m").mainBytes();
  EXPECT_NE(obj.find("v 0 0 0 0.5 0.25 1\n"), std::string::npos);
  EXPECT_NE(encodeGlb(mesh).find("COLOR_0"), std::string::npos);
}

// Issue 14: a material name comes from the imported file; a line break in it must not add
// statements (here a texture naming any file) to the OBJ or MTL we write.
TEST(MeshExport, MaterialNamesCannotAddObjOrMtlStatements) {
  Mesh mesh = sampleMesh(UpAxis::Z);
  mesh.materials[0].name = "glass\nmap_Kd /etc/hostname";
  mesh.materials[1].name = "red\r\nmtllib ../../x.mtl";
  const EncodedMeshFiles files = encodeObj(mesh, "mesh");
  for (const auto& [name, bytes] : files.files) {
    if (name.size() > 4 && name.substr(name.size() - 4) == ".png") continue;
    EXPECT_EQ(bytes.find("/etc/hostname"), std::string::npos) << name;
    EXPECT_EQ(bytes.find("\nmap_Kd /"), std::string::npos) << name;
    EXPECT_EQ(bytes.find("\nmtllib ../"), std::string::npos) << name;
    EXPECT_EQ(bytes.find('\r'), std::string::npos) << name;
  }
  const std::string& mtl = files.files[1].second;
  EXPECT_NE(mtl.find("newmtl glass_map_Kd__etc_hostname\n"), std::string::npos) << mtl;
  EXPECT_NE(files.mainBytes().find("usemtl glass_map_Kd__etc_hostname\n"), std::string::npos);
  // Two names that become the same safe name stay two materials.
  mesh.materials[0].name = "a b";
  mesh.materials[1].name = "a\nb";
  const std::string twins = encodeObj(mesh, "mesh").files[1].second;
  EXPECT_NE(twins.find("newmtl a_b\n"), std::string::npos) << twins;
  EXPECT_NE(twins.find("newmtl a_b-2\n"), std::string::npos) << twins;
}

TEST(MeshExport, RejectsUnknownExtension) {
  EXPECT_THROW(exportMesh(sampleMesh(UpAxis::Z), test::freshTempDir() / "mesh.fbx"), FileError);
}

}  // namespace
}  // namespace sagrid
