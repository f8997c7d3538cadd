#include <gtest/gtest.h>

#include "core/mesh/mesh.h"

namespace sagrid {
namespace {

Mesh oneTriangle(float x, bool withColours) {
  Mesh m;
  m.positions = {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}};
  m.normals.assign(3, Eigen::Vector3f::UnitZ());
  m.triangles = {{0, 1, 2}};
  if (withColours) m.colors.assign(3, Eigen::Vector3f(0.2f, 0.4f, 0.6f));
  return m;
}

TEST(MeshAppend, IndicesMaterialsAndTexturesAreShiftedPastTheMeshsOwn) {
  Mesh a = oneTriangle(0, false);
  a.materials = {{"red", {1, 0, 0}, -1}};
  a.triangleMaterials = {0};
  Mesh b = oneTriangle(5, false);
  Texture t;
  t.width = t.height = 1;
  t.rgba = {10, 20, 30, 255};
  b.textures = {t};
  b.uvs.assign(3, Eigen::Vector2f(0.5f, 0.5f));
  b.materials = {{"wood", {1, 1, 1}, 0}};
  b.triangleMaterials = {0};

  a.append(b);
  ASSERT_EQ(a.triangles.size(), 2u);
  EXPECT_EQ(a.triangles[1], Eigen::Vector3i(3, 4, 5));
  EXPECT_EQ(a.positions[3], Eigen::Vector3f(5, 0, 0));
  ASSERT_EQ(a.materials.size(), 2u);
  EXPECT_EQ(a.triangleMaterials, (std::vector<int>{0, 1}));
  EXPECT_EQ(a.materials[1].texture, 0);
  ASSERT_EQ(a.textures.size(), 1u);
  // UVs only the part had are padded with zeros on the mesh's own vertices.
  ASSERT_EQ(a.uvs.size(), 6u);
  EXPECT_EQ(a.uvs[0], Eigen::Vector2f::Zero());
  EXPECT_EQ(a.uvs[4], Eigen::Vector2f(0.5f, 0.5f));
  EXPECT_EQ(a.normals.size(), 6u);
  EXPECT_NEAR(a.albedo(1, 0.2f, 0.2f).x(), 10.0f / 255.0f, 1e-3f);
  EXPECT_NEAR(a.albedo(0, 0.2f, 0.2f).x(), 1.0f, 1e-6f);
}

TEST(MeshAppend, AttributesOnlyOneSideHasArePaddedSoEveryVertexKeepsOne) {
  Mesh a = oneTriangle(0, true);
  a.append(oneTriangle(2, false));
  ASSERT_EQ(a.colors.size(), 6u);
  EXPECT_EQ(a.colors[0], Eigen::Vector3f(0.2f, 0.4f, 0.6f));
  EXPECT_EQ(a.colors[5], Eigen::Vector3f::Ones());
  EXPECT_TRUE(a.uvs.empty());
  EXPECT_TRUE(a.triangleMaterials.empty());

  // A part with materials gives a material-less mesh a white default for its own triangles.
  Mesh c = oneTriangle(0, false);
  Mesh d = oneTriangle(1, false);
  d.materials = {{"blue", {0, 0, 1}, -1}};
  d.triangleMaterials = {0};
  c.append(d);
  ASSERT_EQ(c.materials.size(), 2u);
  EXPECT_EQ(c.triangleMaterials, (std::vector<int>{0, 1}));
  EXPECT_EQ(c.albedo(0, 0.1f, 0.1f), Eigen::Vector3f::Ones());
  EXPECT_EQ(c.albedo(1, 0.1f, 0.1f), Eigen::Vector3f(0, 0, 1));
}

}  // namespace
}  // namespace sagrid
