#include "core/features/surface_samples.h"

#include <algorithm>
#include <cmath>

#include "core/mesh/mesh.h"
#include "core/render/trellis_views.h"

namespace sagrid {

std::vector<int> occupiedSlots(const VoxelGrid& grid) {
  std::vector<int> slots(grid.voxelCount(), -1);
  int next = 0;
  const auto& occ = grid.occupancy();
  for (std::size_t i = 0; i < occ.size(); ++i) {
    if (occ[i]) slots[i] = next++;
  }
  return slots;
}

std::vector<VoxelSurfaceStats> voxelSurfaceStats(const Mesh& mesh, const VoxelGrid& grid,
                                                 float samplesPerVoxelFace) {
  std::vector<VoxelSurfaceStats> stats(grid.occupiedCount());
  const std::vector<int> slots = occupiedSlots(grid);
  const float h = 1.0f / grid.resolution();
  const float areaPerSample = h * h / samplesPerVoxelFace;
  constexpr int kMaxSamplesPerTriangle = 1 << 20;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3f& a = mesh.positions[tri[0]];
    const Eigen::Vector3f& b = mesh.positions[tri[1]];
    const Eigen::Vector3f& c = mesh.positions[tri[2]];
    const Eigen::Vector3f cross = (b - a).cross(c - a);
    const float area = 0.5f * cross.norm();
    if (!(area > 0.0f)) continue;  // degenerate (or NaN) triangles carry no surface
    const Eigen::Vector3f n = cross.normalized();
    const int count = static_cast<int>(
        std::clamp(std::ceil(area / areaPerSample), 1.0f, static_cast<float>(kMaxSamplesPerTriangle)));
    const float weight = area / count;
    const std::array<float, 6> nn{n.x() * n.x(), n.y() * n.y(), n.z() * n.z(),
                                  n.x() * n.y(), n.x() * n.z(), n.y() * n.z()};
    for (int s = 0; s < count; ++s) {
      // Stratified in one barycentric direction, van der Corput in the other: uniform over the
      // triangle and deterministic.
      const float r1 = (s + 0.5f) / count;
      const float r2 = static_cast<float>(radicalInverse(2, static_cast<std::uint64_t>(s) + 1));
      const float sq = std::sqrt(r1);
      const float u = sq * (1.0f - r2), v = sq * r2;  // weights of b and c
      const Eigen::Vector3f p = a + u * (b - a) + v * (c - a);
      const VoxelIndex vi = voxelContaining(p, grid.resolution());
      const int slot = slots[grid.linearIndex(vi)];
      if (slot < 0) continue;  // only possible through rounding at a voxel face
      VoxelSurfaceStats& st = stats[slot];
      st.area += weight;
      const Eigen::Vector3f albedo = mesh.albedo(static_cast<int>(t), u, v);
      for (int k = 0; k < 3; ++k) st.albedo[k] += weight * albedo[k];
      for (int k = 0; k < 6; ++k) st.normalTensor[k] += weight * nn[k];
    }
  }
  return stats;
}

}  // namespace sagrid
