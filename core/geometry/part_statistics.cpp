#include "core/geometry/part_statistics.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "core/geometry/connected_parts.h"
#include "core/geometry/material_parts.h"
#include "core/mesh/mesh.h"

namespace sagrid {
namespace {

struct Family {
  int members = 0;
  float width = 0, height = 0, flatness = 0;
};

// The families of copies among `instances` (indices into parts): each instance with its copies
// that are instances too, each instance in one family; most members first, then widest.
std::vector<Family> families(const std::vector<ConnectedPart>& parts,
                             const std::vector<std::size_t>& instances, const PartCopies& copies,
                             const Eigen::AlignedBox3f& bounds, float extent) {
  const std::set<std::size_t> isInstance(instances.begin(), instances.end());
  std::set<std::size_t> seen;
  const float bottom = bounds.min().z(), tall = std::max(bounds.sizes().z(), 1e-12f);
  std::vector<Family> out;
  for (std::size_t p : instances) {
    if (seen.count(p)) continue;
    Family family;
    float heights = 0;
    for (std::size_t q : copies.familyOf(p)) {
      if (!isInstance.count(q) || !seen.insert(q).second) continue;
      family.members += 1;
      heights += (parts[q].centroid.z() - bottom) / tall;
    }
    const Eigen::Vector3f size = parts[p].box.sizes();
    const float wide = size.head<2>().maxCoeff();
    family.width = wide / extent;
    family.height = heights / static_cast<float>(family.members);
    family.flatness = wide > 0 ? std::min(1.0f, size.z() / wide) : 1.0f;
    out.push_back(family);
  }
  std::stable_sort(out.begin(), out.end(), [](const Family& a, const Family& b) {
    return a.members != b.members ? a.members > b.members : a.width > b.width;
  });
  return out;
}

float logCount(std::size_t n) { return std::log1p(static_cast<float>(n)); }

}  // namespace

std::array<float, kPartStatisticsSize> partStatistics(const Mesh& mesh) {
  return partStatistics(mesh, connectedAndMaterialParts(mesh));
}

std::array<float, kPartStatisticsSize> partStatistics(const Mesh& mesh,
                                                      const std::vector<ConnectedPart>& parts) {
  std::array<float, kPartStatisticsSize> out{};
  const Eigen::AlignedBox3f bounds = mesh.bounds();
  if (bounds.isEmpty() || !(bounds.sizes().maxCoeff() > 0)) return out;
  const float extent = bounds.sizes().maxCoeff();
  std::vector<std::size_t> instances, roundFlat;
  std::size_t counted = 0, byMaterial = 0;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (parts[p].triangles < kMinInstanceTriangles) continue;
    ++counted;
    byMaterial += parts[p].byMaterial ? 1 : 0;
    if (!isSmallPart(parts[p], kInstanceDiagonalShare * extent)) continue;
    instances.push_back(p);
    if (isRoundFlatPart(parts[p])) roundFlat.push_back(p);
  }
  const PartCopies copies(parts, kCopyTolerance);
  const auto all = families(parts, instances, copies, bounds, extent);
  const auto round = families(parts, roundFlat, copies, bounds, extent);
  out[0] = logCount(counted);
  out[1] = logCount(instances.size());
  if (!all.empty())
    out[2] = logCount(all[0].members), out[3] = all[0].width, out[4] = all[0].height,
    out[5] = all[0].flatness;
  if (all.size() > 1)
    out[6] = logCount(all[1].members), out[7] = all[1].width, out[8] = all[1].height;
  if (!round.empty())
    out[9] = logCount(round[0].members), out[10] = round[0].width, out[11] = round[0].height;
  std::set<int> materials(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end());
  out[12] = logCount(materials.size());
  out[13] = counted ? static_cast<float>(byMaterial) / static_cast<float>(counted) : 0.0f;
  return out;
}

}  // namespace sagrid
