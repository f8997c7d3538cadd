#include "core/render/view_camera.h"

#include <Eigen/Geometry>
#include <cmath>

namespace sagrid {

ViewCamera ViewCamera::lookAtOrigin(float yaw, float pitch, float radius, float fov) {
  ViewCamera cam;
  cam.yaw = yaw;
  cam.pitch = pitch;
  cam.radius = radius;
  cam.fov = fov;
  const Eigen::Vector3f position(radius * std::cos(yaw) * std::cos(pitch),
                                 radius * std::sin(yaw) * std::cos(pitch),
                                 radius * std::sin(pitch));
  const Eigen::Vector3f forward = -position.normalized();
  Eigen::Vector3f right = forward.cross(Eigen::Vector3f::UnitZ());
  if (right.norm() < 1e-6f) {
    // Straight above or below: up is undefined; keep the yaw direction so views stay continuous.
    right = Eigen::Vector3f(std::sin(yaw), -std::cos(yaw), 0.0f);
  }
  right.normalize();
  const Eigen::Vector3f up = right.cross(forward);
  // OpenCV axes: x right, y down, z forward.
  cam.cameraToWorld.block<3, 1>(0, 0) = right;
  cam.cameraToWorld.block<3, 1>(0, 1) = -up;
  cam.cameraToWorld.block<3, 1>(0, 2) = forward;
  cam.cameraToWorld.block<3, 1>(0, 3) = position;
  return cam;
}

Eigen::Matrix4f ViewCamera::extrinsics() const {
  Eigen::Matrix4f w2c = Eigen::Matrix4f::Identity();
  const Eigen::Matrix3f rt = rotation().transpose();
  w2c.block<3, 3>(0, 0) = rt;
  w2c.block<3, 1>(0, 3) = -rt * position();
  return w2c;
}

Eigen::Matrix3f ViewCamera::intrinsics() const {
  const float f = 0.5f / std::tan(fov / 2.0f);
  Eigen::Matrix3f k = Eigen::Matrix3f::Identity();
  k(0, 0) = f;
  k(1, 1) = f;
  k(0, 2) = 0.5f;
  k(1, 2) = 0.5f;
  return k;
}

Eigen::Matrix4f ViewCamera::blenderTransform() const {
  // TRELLIS turns transform_matrix into OpenCV with c2w[:3, 1:3] *= -1; this is the inverse.
  Eigen::Matrix4f m = cameraToWorld;
  m.block<3, 2>(0, 1) *= -1.0f;
  return m;
}

Eigen::Vector2f ViewCamera::project(const Eigen::Vector3f& world, float* depth) const {
  const Eigen::Vector3f c = rotation().transpose() * (world - position());
  if (depth) *depth = c.z();
  const float f = 0.5f / std::tan(fov / 2.0f);
  return {f * c.x() / c.z() + 0.5f, f * c.y() / c.z() + 0.5f};
}

Eigen::Vector3f ViewCamera::rayDirection(float u, float v) const {
  const float f = 0.5f / std::tan(fov / 2.0f);
  return rotation() * Eigen::Vector3f((u - 0.5f) / f, (v - 0.5f) / f, 1.0f);
}

}  // namespace sagrid
