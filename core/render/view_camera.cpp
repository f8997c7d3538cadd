#include "core/render/view_camera.h"

#include <Eigen/Geometry>
#include <cmath>

namespace sagrid {

namespace {
// Normalized focal length (fx = fy) of a square image with full field of view `fov`.
float focalLength(float fov) { return 0.5f / std::tan(fov / 2.0f); }

Eigen::Vector3f directionThrough(const Eigen::Matrix3f& rotation, float f, float u, float v) {
  return rotation * Eigen::Vector3f((u - 0.5f) / f, (v - 0.5f) / f, 1.0f);
}
}  // namespace

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
  const float f = focalLength(fov);
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
  const float f = focalLength(fov);
  return {f * c.x() / c.z() + 0.5f, f * c.y() / c.z() + 0.5f};
}

Eigen::Vector3f ViewCamera::rayDirection(float u, float v) const {
  return directionThrough(rotation(), focalLength(fov), u, v);
}

void ViewCamera::pixelRayDirections(int size, std::vector<Eigen::Vector3f>& out) const {
  const Eigen::Matrix3f r = rotation();
  const float f = focalLength(fov);
  out.resize(static_cast<std::size_t>(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      out[static_cast<std::size_t>(y) * size + x] =
          directionThrough(r, f, (x + 0.5f) / size, (y + 0.5f) / size);
}

}  // namespace sagrid
