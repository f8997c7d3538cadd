// Textures in a sibling folder of the mesh's (Gazebo's model/meshes + model/materials/textures)
// are read when they stay inside the object's folder, and only then.
#include "core/mesh/object_folder.h"

#include <gtest/gtest.h>
#include <webp/encode.h>

#include "core/mesh/mesh_import.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

std::string webpPixel() {
  const std::uint8_t rgba[4] = {10, 200, 30, 255};
  std::uint8_t* out = nullptr;
  const std::size_t size = WebPEncodeLosslessRGBA(rgba, 1, 1, 4, &out);
  std::string bytes(reinterpret_cast<const char*>(out), size);
  WebPFree(out);
  return bytes;
}

// object/meshes/m.obj whose material's texture is `texture` (as the MTL writes it).
fs::path gazeboObject(const fs::path& object, const std::string& texture) {
  fs::create_directories(object / "meshes");
  fs::create_directories(object / "materials" / "textures");
  test::writeFile(object / "materials" / "textures" / "steel.webp", webpPixel());
  test::writeFile(object / "meshes" / "m.mtl", "newmtl steel\nKd 1 1 1\nmap_Kd " + texture + "\n");
  return test::writeFile(object / "meshes" / "m.obj",
                         "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl steel\nf 1/1 2/2 3/3\n");
}

TEST(ObjectFolder, ASiblingTextureFolderIsReadInsideAMarkedObjectFolder) {
  const fs::path object = test::freshTempDir() / "stove";
  const fs::path mesh = gazeboObject(object, "../materials/textures/steel.webp");
  EXPECT_EQ(objectFolderOf(mesh), mesh.parent_path());  // no marker yet: the mesh's folder
  EXPECT_TRUE(importMesh(mesh).textures.empty());       // so the sibling folder is out of reach
  test::writeFile(object / "model.config", "<model/>");
  EXPECT_EQ(fs::absolute(objectFolderOf(mesh)).lexically_normal(), fs::absolute(object).lexically_normal());
  const Mesh read = importMesh(mesh);
  ASSERT_EQ(read.textures.size(), 1u);
  EXPECT_EQ(read.textures[0].rgba[1], 200);
}

TEST(ObjectFolder, AReferenceLeavingTheObjectFolderIsNotRead) {
  const fs::path root = test::freshTempDir();
  test::writeFile(root / "outside.webp", webpPixel());
  const fs::path mesh = gazeboObject(root / "stove", "../../outside.webp");
  test::writeFile(root / "stove" / "model.config", "<model/>");
  EXPECT_TRUE(importMesh(mesh).textures.empty());
}

}  // namespace
}  // namespace sagrid
