#include "ui/render/camera.h"

#include <algorithm>
#include <cmath>

namespace sagrid::ui {

namespace {
constexpr float kMaxPitch = 1.55f;  // just short of straight down/up, where yaw degenerates
}

void Camera::frame(const Eigen::AlignedBox3f& bounds) {
  if (bounds.isEmpty()) return;
  m_target = bounds.center();
  m_sceneRadius = std::max(0.5f * bounds.diagonal().norm(), 1e-6f);
  const float aspect = float(m_width) / float(std::max(m_height, 1));
  const float halfFov = 0.5f * std::min(m_fovY, 2.0f * std::atan(std::tan(0.5f * m_fovY) * aspect));
  m_distance = 1.1f * m_sceneRadius / std::sin(halfFov);
  m_yaw = -1.0f;
  m_pitch = 0.45f;
}

void Camera::frameFrom(const Eigen::AlignedBox3f& bounds, float yaw, float pitch) {
  if (bounds.isEmpty()) return;
  frame(bounds);
  m_yaw = yaw;
  m_pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
}

void Camera::set(const Eigen::Vector3f& target, float distance, float yaw, float pitch) {
  m_target = target;
  m_distance = distance;
  m_yaw = yaw;
  m_pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
}

void Camera::orbit(float dYaw, float dPitch) {
  m_yaw += dYaw;
  m_pitch = std::clamp(m_pitch + dPitch, -kMaxPitch, kMaxPitch);
}

void Camera::pan(float dx, float dy) {
  const Eigen::Matrix4f v = view();
  const Eigen::Vector3f right = v.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3f up = v.block<1, 3>(1, 0).transpose();
  const float perPixel = worldPerPixelAt(m_target);
  m_target += (-dx * right + dy * up) * perPixel;
}

void Camera::zoom(float steps) {
  m_distance = std::clamp(m_distance * std::exp(-0.15f * steps), 1e-4f * m_sceneRadius,
                          100.0f * m_sceneRadius);
}

void Camera::zoomTowards(float steps, const Eigen::Vector3f& point) {
  const float before = m_distance;
  zoom(steps);
  // Eye and target scaled about the point by the same factor: the view direction stays, so the
  // ray through the point's pixel still meets it.
  m_target = point + (m_target - point) * (m_distance / before);
}

Eigen::Vector3f Camera::eye() const {
  const float c = std::cos(m_pitch);
  return m_target +
         m_distance * Eigen::Vector3f(c * std::cos(m_yaw), c * std::sin(m_yaw), std::sin(m_pitch));
}

Eigen::Matrix4f Camera::view() const {
  const Eigen::Vector3f e = eye();
  const Eigen::Vector3f f = (m_target - e).normalized();
  const Eigen::Vector3f s = f.cross(Eigen::Vector3f::UnitZ()).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = f.dot(e);
  return m;
}

Eigen::Matrix4f Camera::projection() const {
  const float aspect = float(m_width) / float(std::max(m_height, 1));
  // Near/far follow the distance so depth precision stays good at every zoom.
  const float nearPlane = std::max(m_distance - 4.0f * m_sceneRadius, m_distance * 0.01f);
  const float farPlane = m_distance + 50.0f * m_sceneRadius;
  const float t = 1.0f / std::tan(0.5f * m_fovY);
  Eigen::Matrix4f p = Eigen::Matrix4f::Zero();
  p(0, 0) = t / aspect;
  p(1, 1) = t;
  p(2, 2) = -(farPlane + nearPlane) / (farPlane - nearPlane);
  p(2, 3) = -2.0f * farPlane * nearPlane / (farPlane - nearPlane);
  p(3, 2) = -1.0f;
  return p;
}

Ray Camera::rayThrough(float x, float y) const {
  const Eigen::Matrix4f inverse = viewProjection().inverse();
  const float nx = 2.0f * x / float(m_width) - 1.0f;
  const float ny = 1.0f - 2.0f * y / float(m_height);
  Eigen::Vector4f a = inverse * Eigen::Vector4f(nx, ny, -1.0f, 1.0f);
  Eigen::Vector4f b = inverse * Eigen::Vector4f(nx, ny, 1.0f, 1.0f);
  const Eigen::Vector3f pa = a.head<3>() / a.w();
  const Eigen::Vector3f pb = b.head<3>() / b.w();
  return {pa, (pb - pa).normalized()};
}

bool Camera::project(const Eigen::Vector3f& point, Eigen::Vector2f& pixel) const {
  const Eigen::Vector4f clip = viewProjection() * point.homogeneous();
  if (!(clip.w() > 1e-8f)) return false;  // behind the eye, or NaN
  const Eigen::Vector3f ndc = clip.head<3>() / clip.w();
  pixel = {(ndc.x() + 1.0f) * 0.5f * float(m_width), (1.0f - ndc.y()) * 0.5f * float(m_height)};
  return pixel.allFinite();
}

float Camera::worldPerPixelAt(const Eigen::Vector3f& point) const {
  const float depth = std::max((point - eye()).dot((m_target - eye()).normalized()), 1e-6f);
  return 2.0f * depth * std::tan(0.5f * m_fovY) / float(std::max(m_height, 1));
}

}  // namespace sagrid::ui
