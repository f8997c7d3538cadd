#include "core/render/trellis_views.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "core/common/error.h"

namespace sagrid {
namespace {

TEST(TrellisViews, RadicalInverseMatchesVanDerCorput) {
  EXPECT_DOUBLE_EQ(radicalInverse(2, 0), 0.0);
  EXPECT_DOUBLE_EQ(radicalInverse(2, 1), 0.5);
  EXPECT_DOUBLE_EQ(radicalInverse(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(radicalInverse(2, 3), 0.75);
  EXPECT_DOUBLE_EQ(radicalInverse(3, 5), 1.0 / 3.0 * 2 + 1.0 / 9.0);  // 5 = 12 in base 3
}

TEST(TrellisViews, SphereHammersleyMatchesTrellisFormula) {
  // TRELLIS: u = n / N + off0 / N, v = radical_inverse(2, n) + off1,
  // pitch = arccos(1 - 2u) - pi / 2, yaw = 2 pi v.
  const Eigen::Vector2f offset(0.3f, 0.7f);
  const int n = 5, count = 150;
  const double u = 5.0 / 150 + 0.3 / 150, v = radicalInverse(2, 5) + 0.7;
  const Eigen::Vector2f yp = sphereHammersley(n, count, offset);
  EXPECT_NEAR(yp.x(), v * 2 * M_PI, 1e-5);
  EXPECT_NEAR(yp.y(), std::acos(1 - 2 * u) - M_PI / 2, 1e-6);
  // Sample 0 without offset looks from straight below.
  EXPECT_NEAR(sphereHammersley(0, count, {0, 0}).y(), -M_PI / 2, 1e-6);
}

TEST(TrellisViews, ViewsCoverTheSphereAtRadiusTwo) {
  const auto views = trellisViews(kTrellisViewCount, seedFromKey("abc"));
  ASSERT_EQ(views.size(), 150u);
  int above = 0;
  Eigen::Vector3f meanDir = Eigen::Vector3f::Zero();
  for (const auto& v : views) {
    EXPECT_NEAR(v.position().norm(), 2.0f, 1e-5f);
    EXPECT_NEAR(v.fov, 40.0f / 180.0f * M_PI, 1e-6);
    above += v.position().z() > 0;
    meanDir += v.position().normalized();
  }
  EXPECT_NEAR(above, 75, 3);                        // Hammersley: evenly above and below
  EXPECT_LT(meanDir.norm() / views.size(), 0.02f);  // and evenly around
  // Same key, same views; different key, different offset.
  EXPECT_TRUE(
      trellisViews(150, seedFromKey("abc"))[2].cameraToWorld.isApprox(views[2].cameraToWorld));
  EXPECT_FALSE(
      trellisViews(150, seedFromKey("abd"))[2].cameraToWorld.isApprox(views[2].cameraToWorld));
}

TEST(ViewCamera, LooksAtOriginWithZUp) {
  const ViewCamera cam = ViewCamera::lookAtOrigin(0.3f, 0.4f, 2.0f, 40.0f / 180.0f * M_PI);
  float depth = 0;
  const Eigen::Vector2f uv = cam.project(Eigen::Vector3f::Zero(), &depth);
  EXPECT_NEAR(uv.x(), 0.5f, 1e-6f);
  EXPECT_NEAR(uv.y(), 0.5f, 1e-6f);
  EXPECT_NEAR(depth, 2.0f, 1e-5f);
  // World +z appears towards the top of the image (smaller v).
  EXPECT_LT(cam.project(Eigen::Vector3f(0, 0, 0.1f)).y(), 0.5f);
  // Extrinsics invert the camera-to-world matrix; the rotation is orthonormal.
  EXPECT_TRUE((cam.extrinsics() * cam.cameraToWorld).isIdentity(1e-5f));
  EXPECT_TRUE((cam.rotation().transpose() * cam.rotation()).isIdentity(1e-5f));
  EXPECT_NEAR(cam.rotation().determinant(), 1.0f, 1e-5f);
  // Normalized intrinsics of a 40 degree FOV.
  EXPECT_NEAR(cam.intrinsics()(0, 0), 0.5f / std::tan(20.0f / 180.0f * M_PI), 1e-5f);
  EXPECT_FLOAT_EQ(cam.intrinsics()(1, 2), 0.5f);
  // Blender's matrix: camera looks down its -z, y up (OpenGL).
  const Eigen::Matrix4f b = cam.blenderTransform();
  EXPECT_TRUE(Eigen::Vector3f(-b.block<3, 1>(0, 2)).isApprox(-cam.position().normalized(), 1e-5f));
  EXPECT_GT(b(2, 1), 0.0f);
}

TEST(ViewCamera, ProjectionAndRayAreInverse) {
  const ViewCamera cam = ViewCamera::lookAtOrigin(-2.0f, -0.7f, 2.0f, 0.7f);
  const Eigen::Vector3f p(0.2f, -0.3f, 0.25f);
  float depth = 0;
  const Eigen::Vector2f uv = cam.project(p, &depth);
  const Eigen::Vector3f back = cam.position() + depth * cam.rayDirection(uv.x(), uv.y());
  EXPECT_TRUE(back.isApprox(p, 1e-5f)) << back.transpose();
}

TEST(ViewCamera, StraightDownViewIsWellDefined) {
  const ViewCamera cam = ViewCamera::lookAtOrigin(0.0f, static_cast<float>(M_PI / 2), 2.0f, 0.7f);
  EXPECT_TRUE(cam.rotation().allFinite());
  EXPECT_NEAR(cam.rotation().determinant(), 1.0f, 1e-5f);
  EXPECT_NEAR(cam.project(Eigen::Vector3f::Zero()).x(), 0.5f, 1e-6f);
}

TEST(TrellisViews, JsonRoundTripKeepsCameras) {
  const auto views = trellisViews(4, 7);
  const nlohmann::json json = camerasToJson(views);
  ASSERT_EQ(json["frames"].size(), 4u);
  EXPECT_EQ(json["frames"][1]["file_path"], "001.png");
  EXPECT_NEAR(json["frames"][0]["intrinsics"][0][2].get<float>(), 0.5f, 1e-7f);
  const auto back = camerasFromJson(nlohmann::json::parse(json.dump()));
  ASSERT_EQ(back.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(back[i].cameraToWorld.isApprox(views[i].cameraToWorld, 1e-6f));
    EXPECT_TRUE(back[i].extrinsics().isApprox(views[i].extrinsics(), 1e-5f));
  }
  EXPECT_THROW(camerasFromJson(nlohmann::json{{"frames", {{{"x", 1}}}}}), Error);
}

}  // namespace
}  // namespace sagrid
