// Ray casts and closest-point queries on a triangle mesh, backed by Embree 3.
// Used to render views for features, to project predicted points onto the surface, and to pick
// and drag points in the GUI.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace sagrid {

struct Mesh;

struct SurfaceHit {
  float distance = 0;         // along the ray (ray direction need not be unit: t value)
  int triangle = -1;
  float u = 0, v = 0;         // Embree barycentrics: p = (1-u-v) v0 + u v1 + v v2
  Eigen::Vector3f position;   // hit point
  Eigen::Vector3f normal;     // unit geometric normal, facing against the ray
};

struct ClosestPoint {
  Eigen::Vector3f position;
  Eigen::Vector3f normal;     // unit geometric normal of the triangle
  int triangle = -1;
  float distance = 0;
};

class SurfaceScene {
 public:
  // Builds the BVH; the mesh is copied (vertex and index buffers), so it may go away afterwards.
  explicit SurfaceScene(const Mesh& mesh);
  ~SurfaceScene();
  SurfaceScene(SurfaceScene&&) noexcept;
  SurfaceScene& operator=(SurfaceScene&&) noexcept;

  std::optional<SurfaceHit> intersect(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction,
                                      float tNear = 0.0f, float tFar = 1e30f) const;
  bool occluded(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction, float tNear,
                float tFar) const;

  // Many rays at once (uses Embree's packet/stream path where it pays); result per ray.
  void intersectMany(const std::vector<Eigen::Vector3f>& origins,
                     const std::vector<Eigen::Vector3f>& directions,
                     std::vector<std::optional<SurfaceHit>>& hits) const;

  ClosestPoint closestPoint(const Eigen::Vector3f& query) const;
  std::vector<ClosestPoint> closestPoints(const std::vector<Eigen::Vector3f>& queries) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace sagrid
