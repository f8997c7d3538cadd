// The mesh's parts finer than connectivity: knobs fused into a body by a shared corner but drawn
// in a material of their own are parts of their own, and nothing is listed twice.
#include "core/geometry/material_parts.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// A unit body with two small knobs, each touching one of its top corners (one connected mesh);
// the body in material 0, the knobs in material 1 unless `oneMaterial`.
Mesh bodyWithFusedKnobs(bool oneMaterial) {
  Mesh mesh = test::box({0, 0, 0}, {1, 1, 1});
  test::append(mesh, test::box({1, 1, 1}, {1.1f, 1.1f, 1.1f}));
  test::append(mesh, test::box({-0.1f, 1, 1}, {0, 1.1f, 1.1f}));
  mesh.materials = {Material{"body"}, Material{"knob"}};
  mesh.triangleMaterials.assign(mesh.triangles.size(), 0);
  if (!oneMaterial) std::fill(mesh.triangleMaterials.begin() + 12, mesh.triangleMaterials.end(), 1);
  return mesh;
}

TEST(MaterialParts, AKnobFusedIntoItsBodyButDrawnInItsOwnMaterialIsAPart) {
  const Mesh mesh = bodyWithFusedKnobs(false);
  const auto connected = connectedParts(mesh);
  ASSERT_EQ(connected.size(), 1u);  // one body through the shared corners
  const auto parts = connectedAndMaterialParts(mesh);
  ASSERT_GE(parts.size(), 3u);
  EXPECT_FALSE(parts[0].byMaterial);
  EXPECT_EQ(parts[0].triangles, connected[0].triangles);
  std::vector<Eigen::Vector3f> knobs;
  for (std::size_t p = 1; p < parts.size(); ++p) {
    EXPECT_TRUE(parts[p].byMaterial);
    if (parts[p].triangles == 12 && parts[p].box.diagonal().norm() < 0.2f)
      knobs.push_back(parts[p].box.center());
  }
  ASSERT_EQ(knobs.size(), 2u);
  std::sort(knobs.begin(), knobs.end(), [](const auto& a, const auto& b) { return a.x() < b.x(); });
  EXPECT_TRUE(knobs[0].isApprox(Eigen::Vector3f(-0.05f, 1.05f, 1.05f), 1e-5f));
  EXPECT_TRUE(knobs[1].isApprox(Eigen::Vector3f(1.05f, 1.05f, 1.05f), 1e-5f));
}

TEST(MaterialParts, OneMaterialOrMaterialsThatAreTheirOwnPartsAddNothing) {
  const Mesh fused = bodyWithFusedKnobs(true);
  EXPECT_EQ(connectedAndMaterialParts(fused).size(), connectedParts(fused).size());
  // Apart from the body, each knob is its own connected part already: not listed again.
  Mesh apart = test::box({0, 0, 0}, {1, 1, 1});
  test::append(apart, test::box({2, 2, 2}, {2.1f, 2.1f, 2.1f}));
  apart.materials = {Material{"body"}, Material{"knob"}};
  apart.triangleMaterials.assign(apart.triangles.size(), 0);
  std::fill(apart.triangleMaterials.begin() + 12, apart.triangleMaterials.end(), 1);
  const auto parts = connectedAndMaterialParts(apart);
  ASSERT_EQ(parts.size(), 2u);
  for (const auto& p : parts) EXPECT_FALSE(p.byMaterial);
  // A mesh without materials: its connected parts.
  EXPECT_EQ(connectedAndMaterialParts(test::box({0, 0, 0}, {1, 1, 1})).size(), 1u);
}

}  // namespace
}  // namespace sagrid
