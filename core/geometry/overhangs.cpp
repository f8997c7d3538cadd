#include "core/geometry/overhangs.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/surface_scene.h"

namespace sagrid {

namespace {

constexpr int kMaxRays = 40000;
constexpr int kMaxHitsPerRay = 64;

// Every surface a vertical ray meets from `origin` up to `length` above it, lowest first.
std::vector<SurfaceHit> hitsUp(const SurfaceScene& scene, const Eigen::Vector3f& origin,
                               float length, float epsilon) {
  std::vector<SurfaceHit> hits;
  float tNear = 0;
  while (static_cast<int>(hits.size()) < kMaxHitsPerRay) {
    const auto hit = scene.intersect(origin, Eigen::Vector3f::UnitZ(), tNear, length);
    if (!hit) break;
    hits.push_back(*hit);
    tNear = hit->distance + epsilon;
  }
  return hits;
}

// Overhang::skyView of a landing point: the share of 8 rays tilted 35 degrees from straight up
// that leave the object.
float skyView(const SurfaceScene& scene, const Eigen::Vector3f& landing, float epsilon) {
  constexpr int kRays = 8;
  constexpr float kTilt = 0.6109f;  // 35 degrees
  int open = 0;
  for (int r = 0; r < kRays; ++r) {
    const float azimuth = 2.0f * 3.14159265f * static_cast<float>(r) / kRays;
    const Eigen::Vector3f direction(std::sin(kTilt) * std::cos(azimuth),
                                    std::sin(kTilt) * std::sin(azimuth), std::cos(kTilt));
    const auto hit = scene.intersect(landing + epsilon * Eigen::Vector3f::UnitZ(), direction);
    if (!hit) ++open;
  }
  return static_cast<float>(open) / kRays;
}

}  // namespace

std::vector<Overhang> overhangsNear(const SurfaceScene& scene, const Eigen::Vector3f& centre,
                                    const OverhangSearch& search) {
  std::vector<Overhang> found;
  if (!(search.radius > 0 && search.step > 0 && search.minDrop > 0 && search.maxDrop > 0))
    return found;
  const int half = static_cast<int>(std::floor(search.radius / search.step));
  if ((2.0 * half + 1) * (2.0 * half + 1) > kMaxRays) return found;
  const float bottom = centre.z() - search.radius - search.maxDrop;
  const float length = 2 * search.radius + search.maxDrop;
  const float epsilon = 1e-3f * search.step;
  for (int a = -half; a <= half; ++a)
    for (int b = -half; b <= half; ++b) {
      const Eigen::Vector3f origin(centre.x() + a * search.step, centre.y() + b * search.step,
                                   bottom);
      const auto hits = hitsUp(scene, origin, length, epsilon);
      for (std::size_t h = 1; h < hits.size(); ++h) {
        const Eigen::Vector3f& top = hits[h].position;
        const float gap = top.z() - hits[h - 1].position.z();
        if (gap < search.minDrop || gap > search.maxDrop) continue;
        if ((top - centre).norm() > search.radius) continue;
        const Eigen::Vector3f middle = 0.5f * (top + hits[h - 1].position);
        if (scene.closestPoint(middle).distance < std::min(search.minClearance, 0.4f * gap))
          continue;
        found.push_back({top, gap, skyView(scene, hits[h - 1].position, epsilon)});
      }
    }
  return found;
}

}  // namespace sagrid
