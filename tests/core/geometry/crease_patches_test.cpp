// Crease patches: the surface split where it turns sharply, so a raised ring modelled into a hob
// is a part of its own although it is one connected body with the hob.
#include "core/geometry/crease_patches.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/geometry/material_parts.h"
#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// A 1 x 1 plate raised by `rise` over x and y in [0.3, 0.7].
Mesh plateWithPlateau(float rise) { return test::plateWithPlateaus(10, 10, rise, {{3, 7, 3, 7}}); }

TEST(CreasePatches, EachFaceOfABoxIsAPatch) {
  const auto patches = creasePatches(test::box({0, 0, 0}, {1, 2, 3}));
  ASSERT_EQ(patches.size(), 6u);
  for (const auto& patch : patches) {
    EXPECT_EQ(patch.triangles, 2);
    EXPECT_FLOAT_EQ(patch.box.sizes().minCoeff(), 0.0f);  // flat
    EXPECT_FALSE(patch.byCrease);                         // the caller flags what it adds
  }
}

TEST(CreasePatches, ACurvedSideIsOnePatchAndItsCapsAreTwoMore) {
  // 32 segments: neighbouring faces of the side turn by 11.25 degrees, the caps by 90.
  const auto patches = creasePatches(test::cylinder(0.5f, 1.0f, 32));
  ASSERT_EQ(patches.size(), 3u);
  EXPECT_NEAR(patches[0].box.sizes().z(), 1.0f, 1e-5f);  // the side, the most triangles
  EXPECT_FLOAT_EQ(patches[1].box.sizes().z(), 0.0f);
  EXPECT_FLOAT_EQ(patches[2].box.sizes().z(), 0.0f);
  // Below the turn between segments (4 segments turn by 90), the side splits at each edge.
  EXPECT_EQ(creasePatches(test::cylinder(0.5f, 1.0f, 4)).size(), 6u);
}

TEST(CreasePatches, APlateauRaisedOutOfOneBodyIsAPartOfItsOwn) {
  const Mesh mesh = plateWithPlateau(0.1f);
  ASSERT_EQ(connectedParts(mesh).size(), 1u);
  const auto patches = creasePatches(mesh);
  const auto top = std::find_if(patches.begin(), patches.end(), [](const ConnectedPart& p) {
    return p.box.min().z() > 0.09f;
  });
  ASSERT_NE(top, patches.end());
  EXPECT_EQ(top->triangles, 32);  // 4 x 4 cells
  EXPECT_TRUE(top->centroid.isApprox(Eigen::Vector3f(0.5f, 0.5f, 0.1f), 1e-5f));
  // A gentle rise (under 30 degrees) is no crease: one patch.
  EXPECT_EQ(creasePatches(plateWithPlateau(0.02f)).size(), 1u);
  // Appended to the connected parts, only the new ones are flagged.
  std::vector<ConnectedPart> parts = connectedParts(mesh);
  appendNewParts(parts, patches, &ConnectedPart::byCrease);
  EXPECT_FALSE(parts[0].byCrease);
  EXPECT_EQ(parts.size(), 1 + patches.size());
  for (std::size_t p = 1; p < parts.size(); ++p) EXPECT_TRUE(parts[p].byCrease);
}

TEST(CreasePatches, FacesWoundAgainstTheirNeighboursStillJoin) {
  Mesh mesh = plateWithPlateau(0.02f);
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
  EXPECT_EQ(creasePatches(mesh).size(), 1u);
  // A mesh of nothing but a triangle of no area, and an empty mesh.
  Mesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.triangles = {{0, 1, 2}};
  EXPECT_EQ(creasePatches(flat).size(), 1u);
  EXPECT_TRUE(creasePatches(Mesh{}).empty());
}

}  // namespace
}  // namespace sagrid
