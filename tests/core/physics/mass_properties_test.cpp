#include "core/physics/mass_properties.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/physics/solid_voxels.h"
#include "support/analytic_meshes.h"

namespace sagrid::physics {
namespace {

// Box a x b x c, density rho: I = m/12 diag(b^2+c^2, a^2+c^2, a^2+b^2).
TEST(MassProperties, BoxMatchesClosedForm) {
  const double a = 1.0, b = 0.6, c = 0.3, rho = 1000;
  MassOptions options;
  options.density = rho;
  const MassProperties m = estimateMassProperties(test::box({0.1f, 0.2f, 0.3f}, {1.1f, 0.8f, 0.6f}), options);
  const double mass = rho * a * b * c;
  EXPECT_NEAR(m.volume, a * b * c, 0.005 * a * b * c);
  EXPECT_NEAR(m.mass, mass, 0.005 * mass);
  EXPECT_TRUE(m.centerOfMass.isApprox(Eigen::Vector3d(0.6, 0.5, 0.45), 1e-3));
  const Eigen::Vector3d expected = mass / 12 * Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.inertia(i, i), expected[i], 0.01 * expected[i]);
  EXPECT_NEAR(m.inertia(0, 1), 0.0, 1e-3 * expected[0]);
  // Principal form: ascending moments, and the rotation rebuilds the full tensor.
  EXPECT_NEAR(m.principalMoments[0], expected[0], 0.01 * expected[0]);
  EXPECT_NEAR(m.principalMoments[2], expected[2], 0.01 * expected[2]);
  const Eigen::Matrix3d r = m.principalAxes.toRotationMatrix();
  EXPECT_TRUE((r * m.principalMoments.asDiagonal() * r.transpose()).isApprox(m.inertia, 1e-9));
  EXPECT_FALSE(m.surfaceOpen);
  EXPECT_TRUE(m.warnings.empty());
}

TEST(MassProperties, SphereMatchesClosedForm) {
  const double r = 0.5, rho = 200;
  MassOptions options;
  options.category = "sink";
  const MassProperties m = estimateMassProperties(test::uvSphere({0, 0, 1}, 0.5f, 96), options);
  EXPECT_EQ(m.density, rho);
  const double volume = 4.0 / 3.0 * M_PI * r * r * r;
  EXPECT_NEAR(m.volume, volume, 0.01 * volume);
  const double inertia = 0.4 * rho * volume * r * r;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.principalMoments[i], inertia, 0.02 * inertia);
  EXPECT_NEAR(m.centerOfMass.z(), 1.0, 1e-3);
}

TEST(MassProperties, UnitsScaleToMetres) {
  // A 100 x 60 x 30 cm box given in centimetres.
  MassOptions options;
  options.metersPerUnit = 0.01;
  options.density = 1000;
  const MassProperties m = estimateMassProperties(test::box({0, 0, 0}, {100, 60, 30}), options);
  EXPECT_NEAR(m.mass, 180.0, 1.0);
  EXPECT_TRUE(m.centerOfMass.isApprox(Eigen::Vector3d(0.5, 0.3, 0.15), 1e-3));
  EXPECT_NEAR(m.inertia(2, 2), 180.0 / 12 * (1.0 + 0.36), 0.02 * 180.0 / 12 * 1.36);
}

TEST(MassProperties, RotatedBoxHasRotatedPrincipalAxes) {
  Mesh turned = test::box({-0.5f, -0.1f, -0.05f}, {0.5f, 0.1f, 0.05f});
  const Eigen::Matrix3f rotation = Eigen::AngleAxisf(0.5f, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  for (auto& p : turned.positions) p = rotation * p;
  MassOptions options;
  options.density = 1000;
  const MassProperties m = estimateMassProperties(turned, options);
  // The smallest moment is about the box's long axis, now turned by 0.5 rad about z.
  const Eigen::Vector3d longAxis = m.principalAxes.toRotationMatrix().col(0);
  EXPECT_NEAR(std::abs(longAxis.dot(rotation.col(0).cast<double>())), 1.0, 1e-3);
  const double mass = 1000 * 1.0 * 0.2 * 0.1;
  EXPECT_NEAR(m.principalMoments[0], mass / 12 * (0.04 + 0.01), 0.05 * mass / 12 * 0.05);
  EXPECT_NEAR(m.principalMoments[2], mass / 12 * (1.0 + 0.04), 0.02 * mass / 12 * 1.04);
}

TEST(MassProperties, OpenSphereIsClosedByTheFill) {
  // Remove the fan of triangles around the top pole: a hole 0.13 across, 4 voxels at 64^3.
  const Mesh closed = test::uvSphere({0, 0, 0}, 1.0f, 48);
  Mesh open = closed;
  open.triangles.clear();
  for (const auto& t : closed.triangles) {
    bool cap = true;
    for (int c = 0; c < 3; ++c) cap = cap && closed.positions[t[c]].z() > 0.99f;
    if (!cap) open.triangles.push_back(t);
  }
  ASSERT_LT(open.triangles.size(), closed.triangles.size());
  MassOptions options;
  options.density = 1;
  options.resolution = 64;
  options.holeClosingVoxels = 2;
  const MassProperties whole = estimateMassProperties(closed, options);
  const MassProperties holed = estimateMassProperties(open, options);
  EXPECT_TRUE(holed.surfaceOpen);
  EXPECT_FALSE(holed.warnings.empty());
  EXPECT_NEAR(holed.volume, whole.volume, 0.01 * whole.volume);
  // Without the closing the outside floods in and only the shell is left.
  options.holeClosingVoxels = 0;
  EXPECT_LT(estimateMassProperties(open, options).volume, 0.5 * whole.volume);
}

TEST(MassProperties, PlaneWeighsItsShellWithAWarning) {
  MassOptions options;
  options.density = 1000;
  const MassProperties m = estimateMassProperties(test::quadZ({0, 0}, {1, 1}, 0), options);
  EXPECT_GT(m.mass, 0.0);
  EXPECT_LT(m.volume, 0.05);
  EXPECT_TRUE(m.surfaceOpen);
  EXPECT_FALSE(m.warnings.empty());
}

TEST(MassProperties, EditedMassScalesInertia) {
  MassOptions options;
  options.density = 1000;
  const MassProperties m = estimateMassProperties(test::box({0, 0, 0}, {1, 1, 1}), options);
  const MassProperties edited = withMass(m, m.mass / 2);
  EXPECT_NEAR(edited.inertia(0, 0), m.inertia(0, 0) / 2, 1e-9);
  EXPECT_NEAR(edited.density, 500, 5);
  EXPECT_TRUE(edited.centerOfMass.isApprox(m.centerOfMass));
  EXPECT_THROW(withMass(m, 0), InvalidArgument);
  EXPECT_THROW(estimateMassProperties(Mesh{}, options), Error);
}

TEST(DensityTable, CategoriesAndDefault) {
  EXPECT_EQ(densityFor("Stove").category, "stove");
  EXPECT_EQ(densityFor("sink").kilogramsPerCubicMetre, 200.0);
  EXPECT_EQ(densityFor("lamp").category, "default");
  for (const auto& entry : densityTable()) EXPECT_FALSE(entry.source.empty());
}

TEST(SolidVoxels, BoxInteriorIsEnclosed) {
  const SolidVoxels s = solidVoxels(test::box({0, 0, 0}, {1, 1, 1}), 32, 1);
  EXPECT_GT(s.enclosedCount, 20u * 20 * 20);
  EXPECT_EQ(s.closedCount, 0u);
  EXPECT_EQ(s.solid.occupiedCount(), s.surface.occupiedCount() + s.enclosedCount);
}

}  // namespace
}  // namespace sagrid::physics
