#include "core/geometry/surface_scene.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/geometry/closest_point_on_triangle.h"
#include "core/mesh/mesh.h"

namespace sagrid {
namespace {

// Axis-aligned box [lo, hi], 12 outward-facing triangles.
Mesh boxMesh(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  Mesh mesh;
  for (int bits = 0; bits < 8; ++bits) {
    mesh.positions.emplace_back(bits & 1 ? hi.x() : lo.x(), bits & 2 ? hi.y() : lo.y(),
                                bits & 4 ? hi.z() : lo.z());
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.emplace_back(q[0], q[1], q[2]);
    mesh.triangles.emplace_back(q[0], q[2], q[3]);
  }
  return mesh;
}

// UV sphere, radius r at the origin.
Mesh sphereMesh(float r, int rings) {
  Mesh mesh;
  const int segments = 2 * rings;
  for (int i = 0; i <= rings; ++i) {
    const float theta = static_cast<float>(M_PI) * i / rings;
    for (int j = 0; j < segments; ++j) {
      const float phi = 2.0f * static_cast<float>(M_PI) * j / segments;
      mesh.positions.emplace_back(r * std::sin(theta) * std::cos(phi),
                                  r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
    }
  }
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const int a = i * segments + j, b = i * segments + (j + 1) % segments;
      const int c = a + segments, d = b + segments;
      mesh.triangles.emplace_back(a, c, d);
      mesh.triangles.emplace_back(a, d, b);
    }
  }
  return mesh;
}

TEST(ClosestPointOnTriangle, EveryVoronoiRegion) {
  const Eigen::Vector3f a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  auto cp = [&](float x, float y, float z) { return closestPointOnTriangle({x, y, z}, a, b, c); };
  EXPECT_TRUE(cp(0.5f, 0.5f, 3).isApprox(Eigen::Vector3f(0.5f, 0.5f, 0)));  // face
  EXPECT_TRUE(cp(-1, -1, 1).isApprox(a));                                      // vertex a
  EXPECT_TRUE(cp(3, -1, 0).isApprox(b));                                       // vertex b
  EXPECT_TRUE(cp(-1, 3, -2).isApprox(c));                                      // vertex c
  EXPECT_TRUE(cp(1, -5, 0).isApprox(Eigen::Vector3f(1, 0, 0)));                // edge ab
  EXPECT_TRUE(cp(-5, 1, 1).isApprox(Eigen::Vector3f(0, 1, 0)));                // edge ac
  EXPECT_TRUE(cp(2, 2, 0).isApprox(Eigen::Vector3f(1, 1, 0)));                 // edge bc
  // Degenerate triangle (segment from a to b, c on it): closest point on the segment.
  EXPECT_TRUE(closestPointOnTriangle({1, 1, 0}, a, b, Eigen::Vector3f(1, 0, 0))
                  .isApprox(Eigen::Vector3f(1, 0, 0)));
}

TEST(SurfaceScene, RayHitsBoxFaceWithDistanceNormalAndBarycentrics) {
  const Mesh mesh = boxMesh({-1, -1, -1}, {1, 1, 1});
  const SurfaceScene scene(mesh);
  const auto hit = scene.intersect({0.25f, -0.5f, 5}, {0, 0, -2});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->distance, 2.0f, 1e-5f);  // t in units of the (non-unit) direction
  EXPECT_TRUE(hit->position.isApprox(Eigen::Vector3f(0.25f, -0.5f, 1), 1e-5f));
  EXPECT_TRUE(hit->normal.isApprox(Eigen::Vector3f(0, 0, 1), 1e-5f));
  // Barycentrics reproduce the hit point on the hit triangle.
  const Eigen::Vector3i& t = mesh.triangles[hit->triangle];
  const Eigen::Vector3f p = (1 - hit->u - hit->v) * mesh.positions[t[0]] +
                            hit->u * mesh.positions[t[1]] + hit->v * mesh.positions[t[2]];
  EXPECT_TRUE(p.isApprox(hit->position, 1e-5f));
  EXPECT_NEAR(mesh.positions[t[0]].z(), 1.0f, 0);

  // From inside, the normal faces the ray (back towards the origin).
  const auto inside = scene.intersect({0, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->distance, 1.0f, 1e-5f);
  EXPECT_TRUE(inside->normal.isApprox(Eigen::Vector3f(-1, 0, 0), 1e-5f));
}

TEST(SurfaceScene, MissesAndRayInterval) {
  const SurfaceScene scene(boxMesh({-1, -1, -1}, {1, 1, 1}));
  EXPECT_FALSE(scene.intersect({0, 0, 5}, {0, 0, 1}).has_value());
  EXPECT_FALSE(scene.intersect({3, 3, 5}, {0, 0, -1}).has_value());
  EXPECT_FALSE(scene.intersect({0, 0, 5}, {0, 0, -1}, 0.0f, 3.9f).has_value());
  const auto far = scene.intersect({0, 0, 5}, {0, 0, -1}, 4.5f);  // skips the top face
  ASSERT_TRUE(far.has_value());
  EXPECT_NEAR(far->distance, 6.0f, 1e-5f);
  EXPECT_TRUE(scene.occluded({0, 0, 5}, {0, 0, -1}, 0.0f, 10.0f));
  EXPECT_FALSE(scene.occluded({0, 0, 5}, {0, 0, -1}, 0.0f, 3.9f));
  EXPECT_FALSE(scene.occluded({0, 0, 5}, {1, 0, 0}, 0.0f, 100.0f));
}

TEST(SurfaceScene, IntersectManyMatchesSingleRays) {
  const SurfaceScene scene(sphereMesh(1.0f, 24));
  std::mt19937 rng(3);
  std::normal_distribution<float> g;
  std::vector<Eigen::Vector3f> origins, directions;
  for (int i = 0; i < 3000; ++i) {  // enough to take the threaded path
    origins.push_back(3.0f * Eigen::Vector3f(g(rng), g(rng), g(rng)).normalized());
    directions.push_back(Eigen::Vector3f(0.3f * g(rng), 0.3f * g(rng), 0.3f * g(rng)) - origins.back());
  }
  std::vector<std::optional<SurfaceHit>> hits;
  scene.intersectMany(origins, directions, hits);
  ASSERT_EQ(hits.size(), origins.size());
  int hitCount = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const auto single = scene.intersect(origins[i], directions[i]);
    ASSERT_EQ(hits[i].has_value(), single.has_value());
    if (!single) continue;
    ++hitCount;
    EXPECT_EQ(hits[i]->triangle, single->triangle);
    EXPECT_NEAR(hits[i]->position.norm(), 1.0f, 0.01f);  // on the tessellated unit sphere
  }
  EXPECT_GT(hitCount, 2500);
  EXPECT_THROW(scene.intersectMany(origins, {}, hits), InvalidArgument);
}

TEST(SurfaceScene, ClosestPointOnBoxIsAnalytic) {
  const SurfaceScene scene(boxMesh({-1, -2, -3}, {1, 2, 3}));
  // Outside a face, beyond an edge, beyond a corner, and inside.
  struct Case { Eigen::Vector3f q, expected; };
  for (const Case& c : {Case{{0.2f, 0.3f, 7}, {0.2f, 0.3f, 3}}, Case{{3, 3, 0.5f}, {1, 2, 0.5f}},
                        Case{{-4, -5, -6}, {-1, -2, -3}}, Case{{0.5f, 0.1f, 0}, {1, 0.1f, 0}}}) {
    const ClosestPoint cp = scene.closestPoint(c.q);
    EXPECT_TRUE(cp.position.isApprox(c.expected, 1e-5f)) << cp.position.transpose();
    EXPECT_NEAR(cp.distance, (c.q - c.expected).norm(), 1e-5f);
    EXPECT_GE(cp.triangle, 0);
  }
  const ClosestPoint top = scene.closestPoint({0.2f, 0.3f, 7});
  EXPECT_NEAR(std::abs(top.normal.z()), 1.0f, 1e-6f);
}

TEST(SurfaceScene, ClosestPointsOnSphereMatchBruteForce) {
  const Mesh mesh = sphereMesh(1.0f, 16);
  const SurfaceScene scene(mesh);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  std::vector<Eigen::Vector3f> queries;
  for (int i = 0; i < 1500; ++i) queries.emplace_back(u(rng), u(rng), u(rng));
  const auto results = scene.closestPoints(queries);
  ASSERT_EQ(results.size(), queries.size());
  for (std::size_t i = 0; i < queries.size(); i += 7) {
    float best = std::numeric_limits<float>::infinity();
    for (const auto& t : mesh.triangles) {
      const Eigen::Vector3f p = closestPointOnTriangle(queries[i], mesh.positions[t[0]],
                                                       mesh.positions[t[1]], mesh.positions[t[2]]);
      best = std::min(best, (p - queries[i]).norm());
    }
    EXPECT_NEAR(results[i].distance, best, 1e-6f);
    // And analytically: distance to the unit sphere, up to the tessellation error.
    EXPECT_NEAR(results[i].distance, std::abs(queries[i].norm() - 1.0f), 0.02f);
    EXPECT_NEAR((results[i].position - queries[i]).norm(), results[i].distance, 1e-5f);
  }
}

TEST(SurfaceScene, EmptySceneHasNoHitsAndNoClosestPoint) {
  const SurfaceScene scene{Mesh{}};
  EXPECT_FALSE(scene.intersect({0, 0, 0}, {1, 0, 0}).has_value());
  const ClosestPoint cp = scene.closestPoint({1, 2, 3});
  EXPECT_EQ(cp.triangle, -1);
  EXPECT_TRUE(std::isinf(cp.distance));
}

TEST(SurfaceScene, MovedSceneStillWorks) {
  SurfaceScene a(boxMesh({-1, -1, -1}, {1, 1, 1}));
  SurfaceScene b = std::move(a);
  EXPECT_NEAR(b.closestPoint({0, 0, 4}).distance, 3.0f, 1e-6f);
}

}  // namespace
}  // namespace sagrid
