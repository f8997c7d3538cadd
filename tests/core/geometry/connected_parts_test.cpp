#include "core/geometry/connected_parts.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// The same box with every triangle on its own three vertices, as an importer leaves a mesh split
// at every seam of normals or UVs.
Mesh splitAtEverySeam(const Mesh& mesh) {
  Mesh split;
  for (const auto& t : mesh.triangles) {
    const int base = static_cast<int>(split.positions.size());
    for (int c = 0; c < 3; ++c)
      split.positions.push_back(mesh.positions[static_cast<std::size_t>(t[c])]);
    split.triangles.emplace_back(base, base + 1, base + 2);
  }
  split.computeVertexNormals();
  return split;
}

TEST(ConnectedParts, SeparateBoxesAreSeparatePartsAndSplitSeamsStayOnePart) {
  Mesh mesh = splitAtEverySeam(test::box({0, 0, 0}, {1, 2, 3}));
  test::append(mesh, test::box({5, 0, 0}, {6, 1, 1}));
  const auto parts = connectedParts(mesh);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].triangles, 12);
  EXPECT_EQ(parts[1].triangles, 12);
  EXPECT_NEAR(parts[0].area, 2 * (1 * 2 + 2 * 3 + 1 * 3), 1e-4);
  EXPECT_NEAR(parts[1].area, 6.0, 1e-4);
  EXPECT_TRUE(parts[0].centroid.isApprox(Eigen::Vector3f(0.5f, 1.0f, 1.5f), 1e-5f));
  EXPECT_TRUE(parts[1].box.min().isApprox(Eigen::Vector3f(5, 0, 0)));
  EXPECT_TRUE(parts[1].box.max().isApprox(Eigen::Vector3f(6, 1, 1)));
  // A box's corners spread by half its sides along its axes, largest first.
  EXPECT_TRUE(parts[0].spread.isApprox(Eigen::Vector3f(1.5f, 1.0f, 0.5f), 1e-4f));
}

TEST(ConnectedParts, CopiesMovedOrTurnedAreCongruentOtherShapesAreNot) {
  Mesh mesh = test::box({0, 0, 0}, {1, 2, 3});
  test::append(mesh, test::box({10, 0, 0}, {12, 1, 3}));     // turned a quarter about z
  test::append(mesh, test::box({20, 0, 0}, {21.3f, 2, 3}));  // 30 % wider
  test::append(mesh, test::uvSphere({30, 0, 0}, 1.0f, 6));   // another shape
  const auto parts = connectedParts(mesh);
  ASSERT_EQ(parts.size(), 4u);
  // Largest triangle count first: the sphere, then the boxes in file order.
  EXPECT_GT(parts[0].triangles, 12);
  const ConnectedPart& box = parts[1];
  EXPECT_TRUE(congruentParts(box, parts[2], 0.05f));
  EXPECT_TRUE(congruentParts(parts[2], box, 0.05f));
  EXPECT_FALSE(congruentParts(box, parts[3], 0.05f));
  EXPECT_FALSE(congruentParts(box, parts[0], 0.05f));
}

TEST(ConnectedParts, AScaledPartIsSimilarWithItsScaleWithinTheLimit) {
  Mesh mesh = test::box({0, 0, 0}, {2, 2, 0.5f});
  test::append(mesh, test::box({5, 0, 0}, {5 + 2.6f, 2.6f, 0.65f}));  // scaled 1.3
  test::append(mesh, test::box({10, 0, 0}, {14, 4, 1}));              // scaled 2
  test::append(mesh, test::box({20, 0, 0}, {22, 2, 2}));              // a cube: other proportions
  const auto parts = connectedParts(mesh);
  ASSERT_EQ(parts.size(), 4u);
  const auto scaled = similarityScale(parts[0], parts[1], kCopyTolerance, 1.5f);
  ASSERT_TRUE(scaled.has_value());
  EXPECT_NEAR(*scaled, 1.3f, 1e-4f);
  EXPECT_NEAR(*similarityScale(parts[1], parts[0], kCopyTolerance, 1.5f), 1 / 1.3f, 1e-4f);
  EXPECT_FALSE(similarityScale(parts[0], parts[2], kCopyTolerance, 1.5f).has_value());
  EXPECT_TRUE(similarityScale(parts[0], parts[2], kCopyTolerance, 2.5f).has_value());
  EXPECT_FALSE(similarityScale(parts[0], parts[3], kCopyTolerance, 2.5f).has_value());
  // PartCopies takes scaled parts as copies only when asked to.
  EXPECT_TRUE(PartCopies(parts, kCopyTolerance).of(0).empty());
  EXPECT_EQ(PartCopies(parts, kCopyTolerance, 1.5f).of(0), std::vector<std::size_t>{1});
}

TEST(ConnectedParts, AnEmptyMeshAndBadIndicesGiveNoParts) {
  EXPECT_TRUE(connectedParts(Mesh{}).empty());
  Mesh broken;
  broken.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  broken.triangles = {{0, 1, 7}, {-1, 0, 1}};
  EXPECT_TRUE(connectedParts(broken).empty());
}

TEST(ConnectedParts, APointLiesOnThePartWhoseBoxIsNearestTheSmallestWhereBoxesHoldIt) {
  // A knob in front of a cabinet door: its box inside the door's box, grown.
  Mesh mesh = test::box({-0.5f, 0.0f, 0.0f}, {0.5f, 0.1f, 1.0f});
  test::append(mesh, test::box({-0.05f, -0.05f, 0.45f}, {0.05f, 0.0f, 0.55f}));
  test::append(mesh, test::box({0.2f, -0.05f, 0.45f}, {0.3f, 0.0f, 0.55f}));
  const auto parts = connectedParts(mesh);
  ASSERT_EQ(parts.size(), 3u);
  const std::size_t door = 0, knob = 1;  // the largest first; the knobs tie, the first first
  // On the knob's front: only the knob's box holds it.
  EXPECT_EQ(partAt({0.0f, -0.05f, 0.5f}, parts, 0.01f), knob);
  // On the door's face behind the knob: both boxes hold it, the knob's is smaller.
  EXPECT_EQ(partAt({0.0f, 0.0f, 0.5f}, parts, 0.01f), knob);
  // On the door far from the knobs.
  EXPECT_EQ(partAt({0.0f, 0.0f, 0.9f}, parts, 0.01f), door);
  // Only small parts: the door is none of them.
  EXPECT_FALSE(partAt({0.0f, 0.0f, 0.9f}, parts, 0.01f, 0.3f).has_value());
  // Nearest of two grown boxes: 0.07 from the first knob, 0.03 from the second.
  EXPECT_EQ(partAt({0.17f, -0.05f, 0.5f}, parts, 0.1f, 0.3f), std::size_t{2});
  EXPECT_FALSE(partAt({0.0f, -1.0f, 0.5f}, parts, 0.1f).has_value());
  EXPECT_TRUE(isSmallPart(parts[knob], 0.3f));
  EXPECT_FALSE(isSmallPart(parts[door], 0.3f));
}

TEST(ConnectedParts, PartCopiesAreTheCongruentOthersAndNoneForDecals) {
  Mesh mesh;
  for (float x : {0.0f, 1.0f, 2.0f})
    test::append(mesh, test::box({x, 0, 0}, {x + 0.2f, 0.2f, 0.2f}));
  test::append(mesh, test::box({3, 0, 0}, {3.4f, 0.2f, 0.2f}));  // another shape
  for (float x : {0.0f, 1.0f}) {  // two equal single triangles: decals
    const int base = static_cast<int>(mesh.positions.size());
    for (const Eigen::Vector3f& p :
         {Eigen::Vector3f(x, 5, 0), Eigen::Vector3f(x + 0.1f, 5, 0), Eigen::Vector3f(x, 5.1f, 0)}) {
      mesh.positions.push_back(p);
      mesh.normals.push_back(Eigen::Vector3f::UnitZ());
    }
    mesh.triangles.emplace_back(base, base + 1, base + 2);
  }
  const auto parts = connectedParts(mesh);
  ASSERT_EQ(parts.size(), 6u);
  const PartCopies copies(parts, kCopyTolerance);
  std::size_t boxCopies = 0, decalCopies = 0;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (parts[p].triangles == 1)
      decalCopies += copies.of(p).size();
    else if (parts[p].box.sizes().x() < 0.3f)
      boxCopies += copies.of(p).size();
    else
      EXPECT_TRUE(copies.of(p).empty());
  }
  EXPECT_EQ(boxCopies, 6u);  // each of three boxes has the two others
  EXPECT_EQ(decalCopies, 0u);
  // The boxes 1 apart: a family of three, each 1 from its nearest other.
  std::size_t first = 0;
  while (parts[first].triangles != 12 || parts[first].box.sizes().x() > 0.3f) ++first;
  const auto family = copies.familyOf(first);
  ASSERT_EQ(family.size(), 3u);
  EXPECT_EQ(family.back(), first);
  for (std::size_t p : family) EXPECT_NEAR(nearestCentroidDistance(p, family, parts), 1.0f, 1e-5f);
  EXPECT_TRUE(std::isinf(nearestCentroidDistance(first, {first}, parts)));
}

}  // namespace
}  // namespace sagrid
