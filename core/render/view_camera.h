// A pinhole camera looking at the origin of the normalized object, in TRELLIS's conventions:
// OpenCV camera axes (x right, y down, z forward), normalized intrinsics (fx = 0.5 / tan(fov/2),
// cx = cy = 0.5, image coordinates u, v in [0, 1] with v growing downwards), extrinsics =
// world-to-camera. Blender's camera-to-world matrix (OpenGL axes), which TRELLIS stores as
// "transform_matrix" in transforms.json, is available for export.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sagrid {

struct ViewCamera {
  Eigen::Matrix4f cameraToWorld = Eigen::Matrix4f::Identity();  // OpenCV axes
  float fov = 0.0f;  // full field of view, radians (square images: x and y alike)
  float yaw = 0.0f, pitch = 0.0f, radius = 0.0f;  // how it was placed (see lookAtOrigin)

  // Camera at radius * (cos yaw cos pitch, sin yaw cos pitch, sin pitch), looking at the origin
  // with world +z as up (Blender's track-to constraint, as TRELLIS's render script sets it).
  static ViewCamera lookAtOrigin(float yaw, float pitch, float radius, float fov);

  Eigen::Vector3f position() const { return cameraToWorld.block<3, 1>(0, 3); }
  Eigen::Matrix3f rotation() const { return cameraToWorld.block<3, 3>(0, 0); }  // camera->world
  Eigen::Matrix4f extrinsics() const;        // world -> camera (OpenCV), TRELLIS "extrinsics"
  Eigen::Matrix3f intrinsics() const;        // normalized, TRELLIS "intrinsics"
  Eigen::Matrix4f blenderTransform() const;  // camera -> world, OpenGL axes ("transform_matrix")

  // Projects a world point: normalized image coordinates (u, v) and depth along the optical axis.
  // Depth <= 0 means the point is behind the camera.
  Eigen::Vector2f project(const Eigen::Vector3f& world, float* depth = nullptr) const;

  // Ray through normalized image coordinates (u, v). The direction is scaled so that the ray
  // parameter t equals depth along the optical axis (z-depth), which is what depth maps store.
  Eigen::Vector3f rayDirection(float u, float v) const;
  // rayDirection through the centre of every pixel of a size x size image, row by row, into
  // `out` (the rotation and focal length worked out once per image, not per pixel).
  void pixelRayDirections(int size, std::vector<Eigen::Vector3f>& out) const;
};

}  // namespace sagrid
