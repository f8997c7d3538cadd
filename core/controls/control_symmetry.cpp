#include "core/controls/control_symmetry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/point_grid.h"
#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

// Samples spread over the part's surface by area (about this many; each triangle at least one).
constexpr int kSurfaceSamples = 1200;
// Samples turned per angle when a direction is scored (every n-th of the surface samples).
constexpr int kTurnedSamples = 100;
// Angles the surface is turned by (degrees): unrelated to the 4-, 6- and 8-fold symmetries of
// low-poly knobs, so that a prism about its axis does not pass for a body of revolution by luck.
constexpr float kTurnDegrees[] = {41.0f, 97.0f, 223.0f};
// Directions tried on the half sphere before refining around the best one.
constexpr int kCoarseDirections = 160;
// Refinement: cones of these half-angles (degrees) around the best direction so far.
constexpr float kRefineDegrees[] = {8.0f, 4.0f, 2.0f, 1.0f, 0.5f};
constexpr int kRefineDirections = 16;
// A turned sample lands on the surface when a sample lies within this many sample spacings.
constexpr float kOnSurfaceSpacings = 1.5f;

struct Samples {
  std::vector<Eigen::Vector3f> points;   // kSurfaceSamples of them, spread evenly by area
  std::vector<Eigen::Vector3f> corners;  // the corners of the triangles with area
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  float spacing = 0;  // typical distance between neighbouring samples
};

// kSurfaceSamples points spread over the triangles' surface evenly by area (stratified along the
// triangles' running area, placed inside each on a fixed low-discrepancy sequence), so that the
// cost does not grow with the triangle count and a finely tessellated region is not sampled more
// densely than a coarse one.
std::optional<Samples> sampleSurface(const Mesh& mesh, const std::vector<int>& triangles) {
  Samples s;
  std::vector<double> running;  // area up to and including each triangle of `corners` / 3
  double total = 0;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (int t : triangles) {
    if (t < 0 || static_cast<std::size_t>(t) >= mesh.triangles.size()) continue;
    const Eigen::Vector3i& f = mesh.triangles[static_cast<std::size_t>(t)];
    bool inRange = true;
    for (int c = 0; c < 3; ++c)
      inRange = inRange && f[c] >= 0 && static_cast<std::size_t>(f[c]) < mesh.positions.size();
    if (!inRange) continue;
    const Eigen::Vector3f& a = mesh.positions[static_cast<std::size_t>(f[0])];
    const Eigen::Vector3f& b = mesh.positions[static_cast<std::size_t>(f[1])];
    const Eigen::Vector3f& c = mesh.positions[static_cast<std::size_t>(f[2])];
    if (!a.allFinite() || !b.allFinite() || !c.allFinite()) return std::nullopt;
    const double area = 0.5 * static_cast<double>((b - a).cross(c - a).norm());
    if (!(area > 0)) continue;
    s.corners.insert(s.corners.end(), {a, b, c});
    running.push_back(total += area);
    weighted += area * ((a + b + c) / 3.0f).cast<double>();
  }
  if (running.empty() || !(total > 0)) return std::nullopt;
  s.centre = (weighted / total).cast<float>();
  for (int i = 0; i < kSurfaceSamples; ++i) {
    const double at = (static_cast<double>(i) + 0.5) / kSurfaceSamples * total;
    const std::size_t t = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(running.begin(), running.end(), at) - running.begin()),
        running.size() - 1);
    // The plastic-number sequence, mapped uniformly onto the triangle.
    const double r1 = std::fmod(0.5 + 0.7548776662466927 * i, 1.0);
    const double r2 = std::fmod(0.5 + 0.5698402909980532 * i, 1.0);
    const float root = static_cast<float>(std::sqrt(r1));
    const Eigen::Vector3f& a = s.corners[3 * t];
    const Eigen::Vector3f& b = s.corners[3 * t + 1];
    const Eigen::Vector3f& c = s.corners[3 * t + 2];
    s.points.push_back((1.0f - root) * a + root * (1.0f - static_cast<float>(r2)) * b +
                       root * static_cast<float>(r2) * c);
  }
  s.spacing = static_cast<float>(std::sqrt(total / kSurfaceSamples));
  return s;
}

struct Turned {
  float offShare = 0;  // of the turned samples, those further than the reach from every sample
  float distance = 0;  // their mean distance to the nearest sample, in reaches, at most 1
};

// How far the samples, turned about `axis` through the centre, land from the surface (`grid` over
// the samples; `reach` the on-surface distance).
Turned turnedAbout(const Samples& s, const PointGrid& grid, float reach, const Eigen::Vector3f& axis) {
  const Eigen::Vector3f a = axis.normalized();
  const std::size_t stride = std::max<std::size_t>(1, s.points.size() / kTurnedSamples);
  double off = 0, distance = 0;
  std::size_t n = 0;
  for (float degrees : kTurnDegrees) {
    const Eigen::AngleAxisf turn(degrees * static_cast<float>(M_PI) / 180.0f, a);
    for (std::size_t i = 0; i < s.points.size(); i += stride, ++n) {
      const float d = grid.distanceWithin(s.centre + turn * (s.points[i] - s.centre), reach) / reach;
      off += d >= 1.0f, distance += d;
    }
  }
  const double count = static_cast<double>(std::max<std::size_t>(n, 1));
  return {static_cast<float>(off / count), static_cast<float>(distance / count)};
}

// Directions on the half sphere around +z, spread evenly (a Fibonacci spiral).
std::vector<Eigen::Vector3f> halfSphere(int count) {
  std::vector<Eigen::Vector3f> out;
  const float golden = static_cast<float>(M_PI) * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < count; ++i) {
    const float z = 1.0f - (static_cast<float>(i) + 0.5f) / static_cast<float>(count);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = golden * static_cast<float>(i);
    out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return out;
}

// `count` directions on the cone of half-angle `degrees` around `axis`.
std::vector<Eigen::Vector3f> coneAround(const Eigen::Vector3f& axis, float degrees, int count) {
  const Eigen::Vector3f a = axis.normalized();
  Eigen::Vector3f u = a.unitOrthogonal(), v = a.cross(u);
  const float t = degrees * static_cast<float>(M_PI) / 180.0f;
  std::vector<Eigen::Vector3f> out;
  for (int i = 0; i < count; ++i) {
    const float phi = 2.0f * static_cast<float>(M_PI) * static_cast<float>(i) / static_cast<float>(count);
    out.push_back((std::cos(t) * a + std::sin(t) * (std::cos(phi) * u + std::sin(phi) * v)).normalized());
  }
  return out;
}

}  // namespace

std::optional<RevolutionAxis> revolutionAxis(const Mesh& mesh, const std::vector<int>& triangles,
                                             const std::optional<Eigen::Vector3f>& reference) {
  if (reference && (!reference->allFinite() || reference->norm() <= 0)) return std::nullopt;
  const auto samples = sampleSurface(mesh, triangles);
  if (!samples) return std::nullopt;
  const float reach = kOnSurfaceSpacings * samples->spacing;
  Eigen::AlignedBox3f box;
  for (const auto& p : samples->points) box.extend(p);
  const PointGrid grid(samples->points, box, reach);
  RevolutionAxis best;
  best.centre = samples->centre;
  // Directions are ranked by the share landing off the surface, ties (every direction near a
  // body's axis lands all of it on) by how near the turned samples land.
  float bestDistance = std::numeric_limits<float>::infinity();
  best.misfit = std::numeric_limits<float>::infinity();
  const auto consider = [&](const Eigen::Vector3f& direction) {
    const Turned t = turnedAbout(*samples, grid, reach, direction);
    if (t.offShare < best.misfit || (t.offShare == best.misfit && t.distance < bestDistance))
      best.misfit = t.offShare, bestDistance = t.distance, best.axis = direction.normalized();
  };
  for (const auto& d : halfSphere(kCoarseDirections)) consider(d);
  for (float degrees : kRefineDegrees) {
    const Eigen::Vector3f around = best.axis;
    for (const auto& d : coneAround(around, degrees, kRefineDirections)) consider(d);
  }
  if (reference) best.referenceMisfit = turnedAbout(*samples, grid, reach, *reference).offShare;
  float low = std::numeric_limits<float>::infinity(), high = -low;
  for (const auto& p : samples->corners) {
    const float h = (p - best.centre).dot(best.axis);
    low = std::min(low, h), high = std::max(high, h);
    best.radius = std::max(best.radius, (p - best.centre - h * best.axis).norm());
  }
  best.length = high - low;
  return best;
}

}  // namespace sagrid
