#include "core/mesh/mesh_crop.h"

#include <gtest/gtest.h>

#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

TEST(MeshCrop, KeepsTheTrianglesWhoseCentroidIsInsideWithTheirAttributes) {
  Mesh mesh = test::box({0, 0, 0}, {1, 1, 1});
  test::append(mesh, test::box({3, 0, 0}, {4, 1, 1}));
  test::paint(mesh, {0.2f, 0.4f, 0.6f});
  mesh.triangleMaterials.assign(mesh.triangleCount(), 0);
  mesh.materials.push_back(Material{"m", {1, 1, 1}, -1});
  const Mesh crop = cropMesh(mesh, Eigen::AlignedBox3f(Eigen::Vector3f(2.5f, -1, -1),
                                                       Eigen::Vector3f(5, 2, 2)));
  EXPECT_EQ(crop.triangleCount(), mesh.triangleCount() / 2);  // the second box, whole
  EXPECT_EQ(crop.triangleMaterials.size(), crop.triangleCount());
  EXPECT_EQ(crop.colors.size(), crop.positions.size());
  EXPECT_EQ(crop.normals.size(), crop.positions.size());
  EXPECT_EQ(crop.materials.size(), 1u);
  // Only the vertices the kept triangles use, at their original coordinates.
  EXPECT_TRUE(crop.bounds().isApprox(
      Eigen::AlignedBox3f(Eigen::Vector3f(3, 0, 0), Eigen::Vector3f(4, 1, 1))));
  for (const auto& c : crop.colors) EXPECT_TRUE(c.isApprox(Eigen::Vector3f(0.2f, 0.4f, 0.6f)));
}

TEST(MeshCrop, ClipsTrianglesCrossingTheBoxAndInterpolatesTheirAttributes) {
  Mesh quad = test::quadZ({0, 0}, {2, 2}, 0.5f);  // two triangles, UVs over [0,1]^2
  const Mesh crop = cropMesh(quad, Eigen::AlignedBox3f(Eigen::Vector3f(0.5f, 0.5f, 0),
                                                       Eigen::Vector3f(1, 1, 1)));
  ASSERT_GE(crop.triangleCount(), 2u);
  EXPECT_TRUE(crop.bounds().isApprox(Eigen::AlignedBox3f(Eigen::Vector3f(0.5f, 0.5f, 0.5f),
                                                         Eigen::Vector3f(1, 1, 0.5f))));
  double area = 0;
  for (const auto& t : crop.triangles)
    area += 0.5 * (crop.positions[t[1]] - crop.positions[t[0]])
                      .cross(crop.positions[t[2]] - crop.positions[t[0]])
                      .norm();
  EXPECT_NEAR(area, 0.25, 1e-5);
  ASSERT_EQ(crop.uvs.size(), crop.positions.size());
  for (std::size_t v = 0; v < crop.positions.size(); ++v)  // UV = position / 2 on this quad
    EXPECT_TRUE(crop.uvs[v].isApprox(crop.positions[v].head<2>() / 2.0f, 1e-5f));
}

TEST(MeshCrop, AnEmptyBoxGivesAnEmptyMesh) {
  const Mesh mesh = test::box({0, 0, 0}, {1, 1, 1});
  const Mesh crop = cropMesh(mesh, Eigen::AlignedBox3f(Eigen::Vector3f(5, 5, 5),
                                                       Eigen::Vector3f(6, 6, 6)));
  EXPECT_EQ(crop.triangleCount(), 0u);
  EXPECT_TRUE(crop.positions.empty());
}

TEST(CropRegion, GrowsTheBoxAroundThePointsByTheMarginAndClipsItToTheObject) {
  const Eigen::AlignedBox3f bounds(Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(2, 1, 1));
  // Margin 0.1 of the largest extent (2) = 0.2 on every side; clipped at y = 0 and z = 1.
  const auto box = regionAround({{1.0f, 0.1f, 0.9f}, {1.2f, 0.3f, 0.9f}}, bounds, 0.1f, 0.6f);
  ASSERT_TRUE(box.has_value());
  EXPECT_TRUE(box->min().isApprox(Eigen::Vector3f(0.8f, 0.0f, 0.7f)));
  EXPECT_TRUE(box->max().isApprox(Eigen::Vector3f(1.4f, 0.5f, 1.0f)));
}

TEST(CropRegion, RefusesRegionsWiderThanTheShareOrOutsideTheObject) {
  const Eigen::AlignedBox3f bounds(Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(2, 1, 1));
  std::string why;
  // 0.2 + 1.4 + 0.2 = 1.8 wide > 0.6 x 2.
  EXPECT_FALSE(regionAround({{0.3f, 0.5f, 0.5f}, {1.7f, 0.5f, 0.5f}}, bounds, 0.1f, 0.6f, &why));
  EXPECT_EQ(why, "the points spread over most of the object");
  EXPECT_FALSE(regionAround({{5.0f, 5.0f, 5.0f}}, bounds, 0.1f, 0.6f, &why));
  EXPECT_EQ(why, "the region around the points lies outside the object");
}

}  // namespace
}  // namespace sagrid
