#include "core/mesh/size_measures.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/mesh/mesh.h"

namespace sagrid {
namespace {

// An axis-aligned box's 12 triangles (z-up), appended to `mesh`.
void addBox(Mesh& mesh, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  const int base = int(mesh.positions.size());
  for (int i = 0; i < 8; ++i)
    mesh.positions.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (const auto& f : faces) {
    mesh.triangles.emplace_back(base + f[0], base + f[1], base + f[2]);
    mesh.triangles.emplace_back(base + f[0], base + f[2], base + f[3]);
  }
}

TEST(SizeMeasures, ARangeIsMeasuredByItsExtentHeightAndCooktop) {
  // A range body 0.76 wide, 0.6 deep, 0.9 tall, with a backguard 0.76 x 0.05 up to 1.1.
  Mesh range;
  addBox(range, {0, 0, 0}, {0.76f, 0.6f, 0.9f});
  addBox(range, {0, 0.55f, 0.9f}, {0.76f, 0.6f, 1.1f});
  const SizeMeasures sizes = measureSizes(range);
  EXPECT_NEAR(sizes.largestExtent, 1.1, 1e-6);
  EXPECT_NEAR(sizes.height, 1.1, 1e-6);
  // The cooktop (0.46 m^2 at 0.9) outweighs the backguard's top (0.04 m^2 at 1.1); the floor face
  // of the body is a base, left out.
  EXPECT_NEAR(sizes.workSurface, 0.9, 1e-6);
  EXPECT_DOUBLE_EQ(sizes[SizeMeasure::WorkSurface], sizes.workSurface);
}

TEST(SizeMeasures, OnlyHorizontalFacesAboveTheBaseAreWorkSurfaces) {
  // A thin plate (a hob's glass): its top is its work surface, its bottom the base left out.
  Mesh plate;
  addBox(plate, {0, 0, 0}, {0.6f, 0.6f, 0.01f});
  EXPECT_NEAR(measureSizes(plate).workSurface, 0.01, 1e-6);
  // A vertical panel has no horizontal face at all.
  Mesh panel;
  panel.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  panel.triangles = {{0, 1, 2}, {0, 2, 3}};
  const SizeMeasures sizes = measureSizes(panel);
  EXPECT_NEAR(sizes.largestExtent, 1.0, 1e-6);
  EXPECT_TRUE(std::isnan(sizes.workSurface));
  EXPECT_TRUE(std::isnan(measureSizes(Mesh{}).largestExtent));
}

TEST(SizeMeasures, NamesReadBackAndUnknownOnesAreRefused) {
  for (const SizeMeasure m : kSizeMeasures) EXPECT_EQ(sizeMeasureNamed(sizeMeasureName(m)), m);
  EXPECT_THROW(sizeMeasureNamed("width"), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
