#include "core/mesh/geometry_identity.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "core/mesh/mesh_import.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

// A box's floor and one wall as four triangles, 0.75 units wide (a cell of 2^-14 units): the
// corners lie on cell centres, so noise far below a cell cannot round them into the next one.
Mesh floorAndWall() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0},     {0.75f, 0, 0}, {0.75f, 0.75f, 0},
                    {0, 0.75f, 0}, {0, 0, 0.75f}, {0.75f, 0, 0.75f}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 5}, {0, 5, 4}};
  return mesh;
}

GeometryIdentity identityOf(const Mesh& mesh) {
  const auto identity = geometryIdentity(mesh);
  EXPECT_TRUE(identity.has_value());
  return identity.value_or(GeometryIdentity{});
}

TEST(GeometryIdentity, IgnoresMaterialsColoursUvsAndHowVerticesAreShared) {
  const GeometryIdentity plain = identityOf(floorAndWall());
  EXPECT_EQ(plain.shape.size(), 32u);

  Mesh painted = floorAndWall();
  painted.materials = {{"red", {1, 0, 0}, -1}, {"chrome", {0.8f, 0.8f, 0.9f}, -1}};
  painted.triangleMaterials = {0, 0, 1, 1};
  painted.colors.assign(painted.positions.size(), Eigen::Vector3f(0.2f, 0.3f, 0.4f));
  painted.uvs.assign(painted.positions.size(), Eigen::Vector2f(0.5f, 0.5f));
  EXPECT_EQ(identityOf(painted), plain);

  // Every triangle with vertices of its own (a UV seam everywhere, as STL stores them), listed
  // from another corner: the same shape and, triangle by triangle, the same order.
  Mesh split;
  const Mesh shared = floorAndWall();
  for (const Eigen::Vector3i& t : shared.triangles) {
    const int base = static_cast<int>(split.positions.size());
    for (int k : {1, 2, 0}) split.positions.push_back(shared.positions[std::size_t(t[k])]);
    split.triangles.push_back({base + 2, base, base + 1});
  }
  EXPECT_EQ(identityOf(split), plain);

  // Triangles in another order (grouped by another material): the same shape, another order.
  Mesh reordered = floorAndWall();
  std::swap(reordered.triangles[0], reordered.triangles[3]);
  const GeometryIdentity moved = identityOf(reordered);
  EXPECT_EQ(moved.shape, plain.shape);
  EXPECT_NE(moved.triangleOrder, plain.triangleOrder);
}

TEST(GeometryIdentity, FloatNoiseBelowACellIsTheSameAMovedVertexIsNot) {
  const GeometryIdentity plain = identityOf(floorAndWall());
  Mesh noisy = floorAndWall();
  for (auto& p : noisy.positions) p += Eigen::Vector3f(3e-7f, -2e-7f, 1e-7f);
  EXPECT_EQ(identityOf(noisy).shape, plain.shape);
  EXPECT_EQ(identityOf(noisy).triangleOrder, plain.triangleOrder);

  Mesh moved = floorAndWall();
  moved.positions[2].z() += 0.01f;  // 1 % of the object's size
  EXPECT_NE(identityOf(moved).shape, plain.shape);

  Mesh flipped = floorAndWall();  // one triangle's winding reversed: faces the other way
  std::swap(flipped.triangles[1][1], flipped.triangles[1][2]);
  EXPECT_NE(identityOf(flipped).shape, plain.shape);
}

TEST(GeometryIdentity, AMovedCopyIsTheSameObjectAtAnotherOrigin) {
  // The same triangles placed elsewhere in the file (not by whole cells, far from the origin):
  // the same shape and order, the origin where its box begins.
  const GeometryIdentity plain = identityOf(floorAndWall());
  EXPECT_EQ(plain.origin, Eigen::Vector3d::Zero());
  const Eigen::Vector3f offset(240.3f, -150.7f, 0.1f);
  Mesh moved = floorAndWall();
  for (auto& p : moved.positions) p += offset;
  const GeometryIdentity there = identityOf(moved);
  EXPECT_EQ(there.shape, plain.shape);
  EXPECT_EQ(there.triangleOrder, plain.triangleOrder);
  EXPECT_TRUE(there.origin.isApprox(offset.cast<double>(), 1e-7)) << there.origin.transpose();
  EXPECT_TRUE(twinOffset(plain, there).isApprox(offset.cast<double>(), 1e-7));
  EXPECT_TRUE(twinOffset(there, plain).isApprox(-offset.cast<double>(), 1e-7));
}

TEST(GeometryIdentity, AScaledRotatedOrMirroredCopyIsAnotherObject) {
  const GeometryIdentity plain = identityOf(floorAndWall());
  for (float scale : {2.0f, 1.5f, 0.5f}) {  // 2 and 0.5: the same cells, another cell size
    Mesh scaled = floorAndWall();
    for (auto& p : scaled.positions) p *= scale;
    EXPECT_NE(identityOf(scaled).shape, plain.shape) << scale;
  }
  // A quarter turn about the vertical: the wall stands on another side of the floor.
  Mesh turned = floorAndWall();
  for (auto& p : turned.positions) p = Eigen::Vector3f(-p.y(), p.x(), p.z());
  EXPECT_NE(identityOf(turned).shape, plain.shape);
  // Mirrored across the wall's plane (and wound back so the faces still face out): the floor
  // lies on the wall's other side.
  Mesh mirrored = floorAndWall();
  for (auto& p : mirrored.positions) p.y() = -p.y();
  for (auto& t : mirrored.triangles) std::swap(t[1], t[2]);
  EXPECT_NE(identityOf(mirrored).shape, plain.shape);
}

TEST(GeometryIdentity, IsOfTheFilesFrameWhateverUpAxisTheImportChose) {
  // The same file coordinates read y-up: positions turned z-up, identity and origin unchanged
  // (labels are in the file's frame, so a twin's points carry by the origins' offset alone).
  Mesh yUp = floorAndWall();
  for (auto& p : yUp.positions) p = fileToZUp(p, UpAxis::Y);
  yUp.fileUp = UpAxis::Y;
  EXPECT_EQ(identityOf(yUp), identityOf(floorAndWall()));
}

TEST(GeometryIdentity, AnEmptyOrFlatToAPointMeshHasNone) {
  EXPECT_FALSE(geometryIdentity(Mesh{}));
  Mesh point;
  point.positions = {{0.3f, 0.3f, 0.3f}, {0.3f, 0.3f, 0.3f}, {0.3f, 0.3f, 0.3f}};
  point.triangles = {{0, 1, 2}};
  EXPECT_FALSE(geometryIdentity(point));
}

TEST(GeometryIdentity, ATriangleNamingAMissingVertexIsAnError) {
  Mesh broken = floorAndWall();
  broken.triangles.push_back({0, 1, 6});
  try {
    geometryIdentity(broken);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("names vertex 6 of a mesh with 6"), std::string::npos)
        << e.what();
  }
}

TEST(GeometryIdentity, TwoFilesOfOneShapeWithOtherMaterialsAndFormats) {
  const fs::path dir = test::freshTempDir();
  std::ofstream(dir / "red.mtl") << "newmtl red\nKd 1 0 0\n";
  std::ofstream(dir / "blue.mtl") << "newmtl blue\nKd 0 0 1\nnewmtl steel\nKd 0.7 0.7 0.7\n";
  const char* vertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n";
  std::ofstream(dir / "red.obj")
      << "mtllib red.mtl\n"
      << vertices
      << "vt 0 0\nvt 1 0\nvt 1 1\nusemtl red\nf 1/1 2/2 3/3\nf 1/1 3/3 4/2\n"
         "f 1/1 2/2 6/3\nf 1/1 6/3 5/2\n";
  std::ofstream(dir / "blue.obj")
      << "mtllib blue.mtl\n"
      << vertices << "usemtl blue\nf 1 2 3\nf 1 3 4\nusemtl steel\nf 1 2 6\nf 1 6 5\n";
  std::ofstream(dir / "tilted.obj")
      << "mtllib blue.mtl\n"
      << vertices << "v 1 1 0.01\nusemtl blue\nf 1 2 7\nf 1 3 4\nusemtl steel\nf 1 2 6\nf 1 6 5\n";
  const ImportOptions zUp(UpAxis::Z);
  const auto red = geometryIdentity(importMesh(dir / "red.obj", zUp));
  const auto blue = geometryIdentity(importMesh(dir / "blue.obj", ImportOptions(UpAxis::Y)));
  const auto tilted = geometryIdentity(importMesh(dir / "tilted.obj", zUp));
  ASSERT_TRUE(red && blue && tilted);
  EXPECT_EQ(red->shape, blue->shape);
  EXPECT_NE(red->shape, tilted->shape);
}

}  // namespace
}  // namespace sagrid
