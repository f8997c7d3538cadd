#include "core/points/surface_projection.h"

#include <gtest/gtest.h>

#include "core/geometry/surface_scene.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

TEST(SurfaceProjection, PutsPointsOnTheSurfaceInTheFileFrame) {
  // A box 2 x 1 x 0.5 (z-up frame) from a y-up file; a point predicted inside it, near its top.
  Mesh mesh = test::box({-1.0f, -0.5f, 0.0f}, {1.0f, 0.5f, 0.5f});
  mesh.fileUp = UpAxis::Y;
  const Normalization n = Normalization::fromMesh(mesh);  // scale 1/2, centre (0, 0, 0.25)
  const SurfaceScene scene(mesh);
  const Eigen::Vector3f inside = n.toNormalized({0.3f, 0.1f, 0.45f});
  const SurfacePoint p = projectToSurface(inside, n, scene, UpAxis::Y);
  const Eigen::Vector3f expectedZUp(0.3f, 0.1f, 0.5f);  // the top face, straight up
  EXPECT_LT((p.position - zUpToFile(expectedZUp, UpAxis::Y)).norm(), 1e-5f);
  EXPECT_LT((p.normal - zUpToFile({0, 0, 1}, UpAxis::Y)).norm(), 1e-5f);
  EXPECT_NEAR(p.moved, 0.05f, 1e-5f);
  // In the y-up file frame "up" is +y.
  EXPECT_NEAR(p.normal.y(), 1.0f, 1e-5f);

  // Points anywhere end on the surface: distance to the box surface is zero.
  for (const Eigen::Vector3f& q :
       {Eigen::Vector3f(0.4f, -0.3f, 0.1f), Eigen::Vector3f(-0.45f, 0.2f, 0.35f),
        Eigen::Vector3f(0.0f, 0.0f, 0.0f)}) {
    const SurfacePoint s = projectToSurface(q, n, scene, UpAxis::Y);
    const Eigen::Vector3f z = fileToZUp(s.position, UpAxis::Y);
    const float toFace =
        std::min({std::abs(z.x() - 1.0f), std::abs(z.x() + 1.0f), std::abs(z.y() - 0.5f),
                  std::abs(z.y() + 0.5f), std::abs(z.z()), std::abs(z.z() - 0.5f)});
    EXPECT_LT(toFace, 1e-5f);
  }
}

}  // namespace
}  // namespace sagrid
