#include "core/points/mirror_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sagrid {

namespace {
// Plane offsets tried on either side of the bounding box's middle, in index-sum units (half
// voxels): a mirror cabinet or a towel bar on one side shifts the box, not the symmetry.
constexpr int kOffsetSearch = 8;
// Where the image's field is read: the smallest predicted distance within this many voxels.
constexpr int kFieldRadius = 2;

// Index into `voxels` per voxel of the N^3 grid (-1 = empty): occupancy and field lookups.
class DenseField {
 public:
  DenseField(const std::vector<VoxelIndex>& voxels, int resolution)
      : m_n(resolution), m_index(static_cast<std::size_t>(m_n) * m_n * m_n, -1) {
    for (std::size_t v = 0; v < voxels.size(); ++v) {
      const auto& x = voxels[v];
      if (inside(x)) m_index[linear(x)] = static_cast<int>(v);
    }
  }
  bool inside(const VoxelIndex& v) const {
    return v.i >= 0 && v.j >= 0 && v.k >= 0 && v.i < m_n && v.j < m_n && v.k < m_n;
  }
  // Field index of a voxel, -1 when empty or outside the grid.
  int at(const VoxelIndex& v) const { return inside(v) ? m_index[linear(v)] : -1; }

 private:
  std::size_t linear(const VoxelIndex& v) const {
    return (static_cast<std::size_t>(v.i) * m_n + v.j) * m_n + v.k;
  }
  int m_n;
  std::vector<int> m_index;
};

VoxelIndex mirrored(VoxelIndex v, const MirrorPlane& plane) {
  if (plane.axis == 0)
    v.i = plane.indexSum - v.i;
  else
    v.j = plane.indexSum - v.j;
  return v;
}

// Whether a voxel within `tolerance` (Chebyshev) of `v` is occupied.
bool occupiedNear(const DenseField& dense, const VoxelIndex& v, int tolerance) {
  for (int a = -tolerance; a <= tolerance; ++a)
    for (int b = -tolerance; b <= tolerance; ++b)
      for (int c = -tolerance; c <= tolerance; ++c)
        if (dense.at({v.i + a, v.j + b, v.k + c}) >= 0) return true;
  return false;
}

// Share of the occupied voxels within `radius` of `centre` whose mirror image has an occupied
// voxel within `tolerance` (0 when the neighbourhood is empty).
float localMatch(const DenseField& dense, const VoxelIndex& centre, const MirrorPlane& plane,
                 int radius, int tolerance) {
  int occupied = 0, matched = 0;
  for (int a = -radius; a <= radius; ++a)
    for (int b = -radius; b <= radius; ++b)
      for (int c = -radius; c <= radius; ++c) {
        const VoxelIndex v{centre.i + a, centre.j + b, centre.k + c};
        if (dense.at(v) < 0) continue;
        ++occupied;
        matched += occupiedNear(dense, mirrored(v, plane), tolerance);
      }
  return occupied ? static_cast<float>(matched) / static_cast<float>(occupied) : 0.0f;
}

// The smallest predicted distance within `radius` voxels of `centre` (infinity when none).
float nearbyDistance(const PredictedField& field, const DenseField& dense, const VoxelIndex& centre,
                     int radius) {
  float best = std::numeric_limits<float>::infinity();
  for (int a = -radius; a <= radius; ++a)
    for (int b = -radius; b <= radius; ++b)
      for (int c = -radius; c <= radius; ++c) {
        const int at = dense.at({centre.i + a, centre.j + b, centre.k + c});
        if (at >= 0) best = std::min(best, field.distances[static_cast<std::size_t>(at)]);
      }
  return best;
}
}  // namespace

float MirrorPlane::coordinate(int resolution) const {
  // Voxel v's centre is (v + 0.5) / N - 0.5; v and indexSum - v are symmetric about the middle.
  return (0.5f * static_cast<float>(indexSum) + 0.5f) / static_cast<float>(resolution) - 0.5f;
}

Eigen::Vector3f MirrorPlane::mirror(const Eigen::Vector3f& p, int resolution) const {
  Eigen::Vector3f out = p;
  out[axis] = 2.0f * coordinate(resolution) - p[axis];
  return out;
}

namespace {
std::optional<MirrorPlane> bestMirrorPlane(const std::vector<VoxelIndex>& voxels, int resolution,
                                           const DenseField& dense, float minSymmetry) {
  std::optional<MirrorPlane> best;
  for (int axis = 0; axis < 2; ++axis) {
    int lo = resolution, hi = -1;
    for (const auto& v : voxels) {
      const int x = axis == 0 ? v.i : v.j;
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
    for (int sum = lo + hi - kOffsetSearch; sum <= lo + hi + kOffsetSearch; ++sum) {
      const MirrorPlane plane{axis, sum, 0.0f};
      std::size_t matched = 0;
      for (const auto& v : voxels) matched += dense.at(mirrored(v, plane)) >= 0;
      const float score = static_cast<float>(matched) / static_cast<float>(voxels.size());
      if (!best || score > best->score) best = MirrorPlane{axis, sum, score};
    }
  }
  if (!best || best->score < minSymmetry) return std::nullopt;
  return best;
}
}  // namespace

std::optional<MirrorPlane> findMirrorPlane(const std::vector<VoxelIndex>& voxels, int resolution,
                                           float minSymmetry) {
  if (voxels.empty() || resolution <= 0) return std::nullopt;
  return bestMirrorPlane(voxels, resolution, DenseField(voxels, resolution), minSymmetry);
}

std::vector<ExtractedPoint> completeMirrorPairs(const PredictedField& field,
                                                const std::vector<ExtractedPoint>& points,
                                                const ExtractionSettings& extraction,
                                                const MirrorPairSettings& settings) {
  if (points.empty() || field.voxels.empty() || field.resolution <= 0) return points;
  const DenseField dense(field.voxels, field.resolution);
  const auto plane = bestMirrorPlane(field.voxels, field.resolution, dense, settings.minSymmetry);
  if (!plane) return points;
  const float suppression = extraction.nmsRadius;
  std::vector<ExtractedPoint> out;
  auto clearOf = [&](const std::vector<ExtractedPoint>& list, const Eigen::Vector3f& p) {
    return std::all_of(list.begin(), list.end(), [&](const ExtractedPoint& q) {
      return (q.position - p).norm() > suppression;
    });
  };
  for (const auto& p : points) {
    out.push_back(p);
    const Eigen::Vector3f image = plane->mirror(p.position, field.resolution);
    if ((image - p.position).norm() <= suppression || !clearOf(points, image) ||
        !clearOf(out, image))
      continue;
    const VoxelIndex at = voxelContaining(p.position, field.resolution);
    if (localMatch(dense, at, *plane, settings.neighbourhoodVoxels,
                   std::max(settings.matchToleranceVoxels, 0)) < settings.minLocalMatch)
      continue;
    const float distance =
        nearbyDistance(field, dense, voxelContaining(image, field.resolution), kFieldRadius);
    if (!std::isfinite(distance)) continue;
    if (settings.maxDistanceAbovePoint >= 0 &&
        distance > p.distance + settings.maxDistanceAbovePoint)
      continue;
    ExtractedPoint twin;
    twin.position = image;
    twin.distance = distance;
    twin.confidence =
        std::exp(-std::max(distance, 0.0f) / std::max(extraction.confidenceScale, 1e-6f));
    out.push_back(twin);
  }
  return out;
}

}  // namespace sagrid
