#include "core/render/trellis_views.h"

#include <cmath>
#include <cstdio>
#include <random>

#include "core/common/error.h"

namespace sagrid {

double radicalInverse(int base, std::uint64_t n) {
  double value = 0.0;
  const double invBase = 1.0 / base;
  double invBaseN = invBase;
  while (n > 0) {
    value += static_cast<double>(n % base) * invBaseN;
    n /= base;
    invBaseN *= invBase;
  }
  return value;
}

Eigen::Vector2f sphereHammersley(int n, int count, const Eigen::Vector2f& offset) {
  // hammersley_sequence(2, n, count) = [n / count, radical_inverse(2, n)]
  const double u = static_cast<double>(n) / count + offset.x() / static_cast<double>(count);
  const double v = radicalInverse(2, static_cast<std::uint64_t>(n)) + offset.y();
  const double theta = std::acos(1.0 - 2.0 * u) - M_PI / 2.0;
  const double phi = v * 2.0 * M_PI;
  return {static_cast<float>(phi), static_cast<float>(theta)};
}

Eigen::Vector2f hammersleyOffset(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double a = uniform(rng);
  const double b = uniform(rng);
  return {static_cast<float>(a), static_cast<float>(b)};
}

std::vector<ViewCamera> trellisViews(int count, std::uint64_t seed, float radius,
                                     float fovDegrees) {
  const Eigen::Vector2f offset = hammersleyOffset(seed);
  const float fov = fovDegrees / 180.0f * static_cast<float>(M_PI);
  std::vector<ViewCamera> views;
  views.reserve(count);
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2f yp = sphereHammersley(i, count, offset);
    views.push_back(ViewCamera::lookAtOrigin(yp.x(), yp.y(), radius, fov));
  }
  return views;
}

std::uint64_t seedFromKey(const std::string& key) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : key) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

namespace {
nlohmann::json matrixJson(const Eigen::MatrixXf& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < m.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (int c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

nlohmann::json camerasToJson(const std::vector<ViewCamera>& views) {
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t i = 0; i < views.size(); ++i) {
    const ViewCamera& v = views[i];
    char name[32];
    std::snprintf(name, sizeof name, "%03zu.png", i);
    frames.push_back({{"file_path", name},
                      {"camera_angle_x", v.fov},
                      {"transform_matrix", matrixJson(v.blenderTransform())},
                      {"extrinsics", matrixJson(v.extrinsics())},
                      {"intrinsics", matrixJson(v.intrinsics())},
                      {"yaw", v.yaw},
                      {"pitch", v.pitch},
                      {"radius", v.radius}});
  }
  return {{"camera_convention", "opencv (x right, y down, z forward); intrinsics normalized"},
          {"frames", frames}};
}

std::vector<ViewCamera> camerasFromJson(const nlohmann::json& json) {
  std::vector<ViewCamera> views;
  try {
    for (const auto& frame : json.at("frames")) {
      ViewCamera v;
      v.fov = frame.at("camera_angle_x").get<float>();
      const auto& m = frame.at("transform_matrix");
      Eigen::Matrix4f blender;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) blender(r, c) = m.at(r).at(c).get<float>();
      v.cameraToWorld = blender;
      v.cameraToWorld.block<3, 2>(0, 1) *= -1.0f;
      v.yaw = frame.value("yaw", 0.0f);
      v.pitch = frame.value("pitch", 0.0f);
      v.radius = frame.value("radius", v.position().norm());
      views.push_back(v);
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error(std::string("camera JSON: ") + e.what());
  }
  return views;
}

}  // namespace sagrid
