#include "core/mesh/geometry_identity.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "core/common/error.h"
#include "core/mesh/mesh_import.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

// A box's floor and one wall as four triangles, 0.75 units wide.
Mesh floorAndWall() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0},     {0.75f, 0, 0}, {0.75f, 0.75f, 0},
                    {0, 0.75f, 0}, {0, 0, 0.75f}, {0.75f, 0, 0.75f}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 5}, {0, 5, 4}};
  return mesh;
}

// 600 triangles on 300 vertices spread over a 100-unit box (a washbasin's size), fixed seed.
Mesh scattered() {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(0.0f, 100.0f);
  std::uniform_int_distribution<int> vertex(0, 299);
  Mesh mesh;
  for (int v = 0; v < 300; ++v)
    mesh.positions.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  for (int t = 0; t < 600; ++t)
    mesh.triangles.push_back({vertex(random), vertex(random), vertex(random)});
  return mesh;
}

Mesh moved(Mesh mesh, const Eigen::Vector3f& offset) {
  for (auto& p : mesh.positions) p += offset;
  return mesh;
}

TEST(GeometryIdentity, IgnoresMaterialsColoursUvsAndHowVerticesAreShared) {
  const Mesh plain = floorAndWall();
  Mesh painted = floorAndWall();
  painted.materials = {{"red", {1, 0, 0}, -1}, {"chrome", {0.8f, 0.8f, 0.9f}, -1}};
  painted.triangleMaterials = {0, 0, 1, 1};
  painted.colors.assign(painted.positions.size(), Eigen::Vector3f(0.2f, 0.3f, 0.4f));
  painted.uvs.assign(painted.positions.size(), Eigen::Vector2f(0.5f, 0.5f));
  auto match = matchGeometry(plain, painted);
  ASSERT_TRUE(match);
  EXPECT_TRUE(match->sameTriangleOrder);
  EXPECT_EQ(match->offset, Eigen::Vector3d::Zero());

  // Every triangle with vertices of its own (a UV seam everywhere, as STL stores them), listed
  // from another corner: the same geometry and, triangle by triangle, the same order.
  Mesh split;
  for (const Eigen::Vector3i& t : plain.triangles) {
    const int base = static_cast<int>(split.positions.size());
    for (int k : {1, 2, 0}) split.positions.push_back(plain.positions[std::size_t(t[k])]);
    split.triangles.push_back({base + 2, base, base + 1});
  }
  match = matchGeometry(plain, split);
  ASSERT_TRUE(match);
  EXPECT_TRUE(match->sameTriangleOrder);

  // Triangles in another order (grouped by another material): the same geometry, another order.
  Mesh reordered = floorAndWall();
  std::swap(reordered.triangles[0], reordered.triangles[3]);
  match = matchGeometry(plain, reordered);
  ASSERT_TRUE(match);
  EXPECT_FALSE(match->sameTriangleOrder);
}

TEST(GeometryIdentity, ATranslatedCopyWithNoiseOnEveryCoordinateMatches) {
  // 240 units away, every coordinate off by up to 1e-4 units (1e-6 of the 100-unit extent): a
  // file printing 4 decimals after moving the model.
  const Mesh plain = scattered();
  const Eigen::Vector3f offset(240.3f, -150.7f, 0.1f);
  Mesh noisy = moved(plain, offset);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> noise(-1e-4f, 1e-4f);
  for (auto& p : noisy.positions) p += Eigen::Vector3f(noise(random), noise(random), noise(random));
  const auto match = matchGeometry(plain, noisy);
  ASSERT_TRUE(match);
  EXPECT_TRUE(match->sameTriangleOrder);
  EXPECT_LT((match->offset - offset.cast<double>()).cwiseAbs().maxCoeff(), 3e-4)
      << match->offset.transpose();
  EXPECT_FALSE(matchGeometry(plain, noisy, 1e-7));  // the noise is there: 1e-6 of the extent
  const auto back = matchGeometry(noisy, plain);
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->offset.isApprox(-match->offset));
  // The outlines are candidates of each other.
  const auto a = geometryOutline(plain), b = geometryOutline(noisy);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->triangles, 600u);
  EXPECT_TRUE(sameOutline(*a, *b));
}

TEST(GeometryIdentity, OneVertexMovedByOnePercentDoesNot) {
  const Mesh plain = scattered();
  Mesh edited = moved(plain, {240, 0, 0});
  // The vertex nearest the box's centre, so the box (and the outline) stays as it was.
  std::size_t inner = 0;
  for (std::size_t v = 0; v < plain.positions.size(); ++v)
    if ((plain.positions[v] - Eigen::Vector3f(50, 50, 50)).norm() <
        (plain.positions[inner] - Eigen::Vector3f(50, 50, 50)).norm())
      inner = v;
  edited.positions[inner].z() += 1.0f;  // 1 % of the object's size
  EXPECT_TRUE(sameOutline(*geometryOutline(plain), *geometryOutline(edited)));
  EXPECT_FALSE(matchGeometry(plain, edited));
  EXPECT_FALSE(matchGeometry(edited, plain));

  Mesh small = floorAndWall();
  small.positions[2].z() += 0.0075f;  // 1 % of 0.75
  EXPECT_FALSE(matchGeometry(floorAndWall(), small));

  Mesh flipped = floorAndWall();  // one triangle's winding reversed: faces the other way
  std::swap(flipped.triangles[1][1], flipped.triangles[1][2]);
  EXPECT_FALSE(matchGeometry(floorAndWall(), flipped));
}

TEST(GeometryIdentity, AScaledRotatedOrMirroredCopyDoesNot) {
  const Mesh plain = floorAndWall();
  for (float scale : {2.0f, 1.01f, 0.5f}) {
    Mesh scaled = floorAndWall();
    for (auto& p : scaled.positions) p *= scale;
    EXPECT_FALSE(matchGeometry(plain, scaled)) << scale;
  }
  // A quarter turn about the vertical: the same box, the wall on another side of the floor.
  Mesh turned = floorAndWall();
  for (auto& p : turned.positions) p = Eigen::Vector3f(-p.y(), p.x(), p.z());
  EXPECT_TRUE(sameOutline(*geometryOutline(plain), *geometryOutline(turned)));
  EXPECT_FALSE(matchGeometry(plain, turned));
  // Mirrored across the wall's plane (and wound back so the faces still face out).
  Mesh mirrored = floorAndWall();
  for (auto& p : mirrored.positions) p.y() = -p.y();
  for (auto& t : mirrored.triangles) std::swap(t[1], t[2]);
  EXPECT_FALSE(matchGeometry(plain, mirrored));
  // The scattered mesh turned by a small angle (0.5 degree) about its centre.
  const Mesh many = scattered();
  Mesh tilted = many;
  const Eigen::Matrix3f turn =
      Eigen::AngleAxisf(0.0087f, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  for (auto& p : tilted.positions)
    p = turn * (p - Eigen::Vector3f(50, 50, 50)) + Eigen::Vector3f(50, 50, 50);
  EXPECT_FALSE(matchGeometry(many, tilted));
}

TEST(GeometryIdentity, DifferentTriangleCountsDoNot) {
  Mesh more = floorAndWall();
  more.triangles.push_back(more.triangles[0]);  // one triangle twice: the same places, one more
  EXPECT_FALSE(sameOutline(*geometryOutline(floorAndWall()), *geometryOutline(more)));
  EXPECT_FALSE(matchGeometry(floorAndWall(), more));
  Mesh fewer = floorAndWall();
  fewer.triangles.pop_back();
  EXPECT_FALSE(matchGeometry(fewer, floorAndWall()));
  // As many triangles, one of them twice in place of another: not the same both ways.
  Mesh doubled = floorAndWall();
  doubled.triangles[1] = doubled.triangles[0];
  EXPECT_FALSE(matchGeometry(floorAndWall(), doubled));
  EXPECT_FALSE(matchGeometry(doubled, floorAndWall()));
}

TEST(GeometryIdentity, IsOfTheFilesFrameWhateverUpAxisTheImportChose) {
  // The same file coordinates read y-up: positions turned z-up, outline and match unchanged
  // (labels are in the file's frame, so a twin's points carry by the origins' offset alone).
  Mesh yUp = floorAndWall();
  for (auto& p : yUp.positions) p = fileToZUp(p, UpAxis::Y);
  yUp.fileUp = UpAxis::Y;
  EXPECT_EQ(*geometryOutline(yUp), *geometryOutline(floorAndWall()));
  const auto match = matchGeometry(yUp, floorAndWall());
  ASSERT_TRUE(match);
  EXPECT_TRUE(match->offset.isZero());
}

TEST(GeometryIdentity, AnEmptyOrFlatToAPointMeshHasNone) {
  EXPECT_FALSE(geometryOutline(Mesh{}));
  EXPECT_FALSE(matchGeometry(Mesh{}, Mesh{}));  // two failed imports are not twins
  EXPECT_FALSE(matchGeometry(Mesh{}, floorAndWall()));
  EXPECT_FALSE(matchGeometry(floorAndWall(), Mesh{}));
  Mesh point;
  point.positions = {{0.3f, 0.3f, 0.3f}, {0.3f, 0.3f, 0.3f}, {0.3f, 0.3f, 0.3f}};
  point.triangles = {{0, 1, 2}};
  EXPECT_FALSE(geometryOutline(point));
  EXPECT_FALSE(matchGeometry(point, point));
}

TEST(GeometryIdentity, ATriangleNamingAMissingVertexOrABadToleranceIsAnError) {
  Mesh broken = floorAndWall();
  broken.triangles.push_back({0, 1, 6});
  try {
    geometryOutline(broken);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("names vertex 6 of a mesh with 6"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(matchGeometry(floorAndWall(), broken), InvalidArgument);
  EXPECT_THROW(matchGeometry(floorAndWall(), floorAndWall(), 0.0), InvalidArgument);
  EXPECT_THROW(matchGeometry(floorAndWall(), floorAndWall(), 1.0), InvalidArgument);
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
  const Mesh red = importMesh(dir / "red.obj", zUp);
  const Mesh blue = importMesh(dir / "blue.obj", ImportOptions(UpAxis::Y));
  const Mesh tilted = importMesh(dir / "tilted.obj", zUp);
  EXPECT_TRUE(matchGeometry(red, blue));
  EXPECT_FALSE(matchGeometry(red, tilted));
}

}  // namespace
}  // namespace sagrid
