// The viewport camera: orbits a target point in SAGrid's z-up frame (yaw about z, pitch above the
// horizon), pans the target, zooms by distance, frames an object's bounds, and turns a pixel
// into a ray for picking and dragging on the surface.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sagrid::ui {

struct Ray {
  Eigen::Vector3f origin;
  Eigen::Vector3f direction;  // unit length
};

class Camera {
 public:
  void setViewport(int width, int height) { m_width = width, m_height = height; }
  int width() const { return m_width; }
  int height() const { return m_height; }

  // Looks at the box centre from the default three-quarter view, far enough to see all of it.
  void frame(const Eigen::AlignedBox3f& bounds);
  // The whole box seen from one side: yaw about z, pitch above the horizon (straight down is
  // clamped just short of it).
  void frameFrom(const Eigen::AlignedBox3f& bounds, float yaw, float pitch);
  void orbit(float deltaYawRadians, float deltaPitchRadians);
  void pan(float dxPixels, float dyPixels);  // moves the target with the screen
  void zoom(float steps);                    // positive = closer
  // Zooms keeping `point` where it is on screen (the wheel over the surface: the spot under the
  // pointer comes closer, not the object's middle).
  void zoomTowards(float steps, const Eigen::Vector3f& point);

  Eigen::Vector3f eye() const;
  const Eigen::Vector3f& target() const { return m_target; }
  float distance() const { return m_distance; }
  float yaw() const { return m_yaw; }
  float pitch() const { return m_pitch; }
  float verticalFovRadians() const { return m_fovY; }
  void set(const Eigen::Vector3f& target, float distance, float yaw, float pitch);

  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection() const;
  Eigen::Matrix4f viewProjection() const { return projection() * view(); }

  // Ray through window pixel (x, y), origin top-left.
  Ray rayThrough(float x, float y) const;
  // Window pixel of a world point; false if it lies behind the camera.
  bool project(const Eigen::Vector3f& point, Eigen::Vector2f& pixel) const;
  // World length of one pixel at the target's depth (for screen-constant marker sizes).
  float worldPerPixelAt(const Eigen::Vector3f& point) const;

 private:
  Eigen::Vector3f m_target = Eigen::Vector3f::Zero();
  float m_distance = 2.0f;
  float m_yaw = -1.0f;    // radians about +z from +x
  float m_pitch = 0.45f;  // radians above the xy plane
  float m_fovY = 0.7f;
  int m_width = 1, m_height = 1;
  float m_sceneRadius = 1.0f;
};

}  // namespace sagrid::ui
