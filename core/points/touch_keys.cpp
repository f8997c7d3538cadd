#include "core/points/touch_keys.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/surface_scene.h"

namespace sagrid {

namespace {
bool isTouchKey(const ConnectedPart& part, float bottom, float top, float voxel,
                const TouchKeySettings& s) {
  if (part.box.isEmpty() || part.triangles < s.minTriangles) return false;
  const Eigen::Vector3f size = part.box.sizes();
  const float wide = std::max(size.x(), size.y()), narrow = std::min(size.x(), size.y());
  return size.z() <= s.maxHeightVoxels * voxel && size.z() <= s.maxFlatness * narrow &&
         wide >= s.minWidthVoxels * voxel && wide <= s.maxWidthVoxels * voxel &&
         wide <= s.maxAspect * narrow &&
         part.box.min().z() >= bottom + s.minHeightShare * (top - bottom);
}

// Whether the key stands on a top that reaches beyond it all round (TouchKeySettings).
bool standsOnTop(const ConnectedPart& part, const SurfaceScene& scene, const Normalization& n,
                 float voxel, const TouchKeySettings& s) {
  const Eigen::Vector3f size = part.box.sizes();
  const Eigen::Vector3f c = part.box.center();
  const float reach = 0.75f * std::max(size.x(), size.y());
  const float drop = n.lengthToMesh(size.z() + 0.5f * voxel);
  int supported = 0;
  for (int k = 0; k < 8; ++k) {
    const float a = static_cast<float>(k) * 0.25f * static_cast<float>(M_PI);
    const Eigen::Vector3f from(c.x() + reach * std::cos(a), c.y() + reach * std::sin(a),
                               part.box.max().z());
    const auto hit = scene.intersect(n.toMesh(from), -Eigen::Vector3f::UnitZ(), 0.0f, drop);
    if (hit && hit->normal.z() >= s.minTopNormal) ++supported;
  }
  return supported >= s.minSupportedRays;
}
}  // namespace

std::vector<TouchKey> findTouchKeys(const std::vector<ConnectedPart>& parts,
                                    const SurfaceScene& scene, const Normalization& normalization,
                                    int resolution, const TouchKeySettings& settings) {
  if (parts.empty() || resolution <= 0) return {};
  float bottom = std::numeric_limits<float>::infinity();
  float top = -std::numeric_limits<float>::infinity();
  for (const ConnectedPart& part : parts) {
    if (part.box.isEmpty()) continue;
    bottom = std::min(bottom, part.box.min().z());
    top = std::max(top, part.box.max().z());
  }
  const float voxel = 1.0f / static_cast<float>(resolution);
  std::vector<TouchKey> keys;
  for (const ConnectedPart& part : parts) {
    if (!isTouchKey(part, bottom, top, voxel, settings) ||
        !standsOnTop(part, scene, normalization, voxel, settings))
      continue;
    const Eigen::Vector3f c = part.box.center();
    const Eigen::Vector3f size = part.box.sizes();
    keys.push_back({{c.x(), c.y(), part.box.max().z()}, 0.5f * std::max(size.x(), size.y())});
  }
  const int n = static_cast<int>(keys.size());
  if (n < settings.fewestKeys || n > settings.mostKeys) return {};
  return keys;
}

}  // namespace sagrid
