#include "core/points/mirror_pairs.h"

#include <algorithm>
#include <cmath>

#include "core/points/field_lookup.h"

namespace sagrid {

namespace {
// Plane offsets tried on either side of the bounding box's middle, in index-sum units (half
// voxels): a mirror cabinet or a towel bar on one side shifts the box, not the symmetry.
constexpr int kOffsetSearch = 8;
// Where the image's field is read: the smallest predicted distance within this many voxels.
constexpr int kFieldRadius = 2;

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

namespace {
// The image of `p` across `plane` when it makes a twin (see completeMirrorPairs): beyond
// `separation` (normalized units) of the point, of `points` and of `out`, a matching
// neighbourhood, and the field low enough there.
std::optional<ExtractedPoint> twinAcross(const MirrorPlane& plane, const ExtractedPoint& p,
                                         const PredictedField& field, const DenseField& dense,
                                         const std::vector<ExtractedPoint>& points,
                                         const std::vector<ExtractedPoint>& out, float separation,
                                         const ExtractionSettings& extraction,
                                         const MirrorPairSettings& settings) {
  auto clearOf = [&](const std::vector<ExtractedPoint>& list, const Eigen::Vector3f& at) {
    return std::all_of(list.begin(), list.end(), [&](const ExtractedPoint& q) {
      return (q.position - at).norm() > separation;
    });
  };
  const Eigen::Vector3f image = plane.mirror(p.position, field.resolution);
  if ((image - p.position).norm() <= separation || !clearOf(points, image) || !clearOf(out, image))
    return std::nullopt;
  const VoxelIndex at = voxelContaining(p.position, field.resolution);
  if (localMatch(dense, at, plane, settings.neighbourhoodVoxels,
                 std::max(settings.matchToleranceVoxels, 0)) < settings.minLocalMatch)
    return std::nullopt;
  const float distance =
      nearbyDistance(field, dense, voxelContaining(image, field.resolution), kFieldRadius);
  if (!std::isfinite(distance)) return std::nullopt;
  if (settings.maxDistanceAbovePoint >= 0 && distance > p.distance + settings.maxDistanceAbovePoint)
    return std::nullopt;
  ExtractedPoint twin;
  twin.position = image;
  twin.distance = distance;
  twin.confidence = confidenceOf(distance, extraction);
  return twin;
}

// Whether the straight segment from `a` to `b` runs through occupied voxels only: one part
// reaching across (a single lever over the spout), not two.
bool occupiedBetween(const DenseField& dense, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                     int resolution) {
  const int steps = std::max(
      1, static_cast<int>(std::ceil(2.0f * (b - a).norm() * static_cast<float>(resolution))));
  for (int s = 0; s <= steps; ++s) {
    const Eigen::Vector3f at = a + (b - a) * (static_cast<float>(s) / static_cast<float>(steps));
    if (dense.at(voxelContaining(at, resolution)) < 0) return false;
  }
  return true;
}

// The vertical plane through `anchor` normal to `axis` (0 = x, 1 = y).
MirrorPlane planeThrough(const Eigen::Vector3f& anchor, int axis, int resolution) {
  // In voxel units the anchor sits at (c + 0.5) N - 0.5; v mirrors to twice that minus v.
  const float voxel = (anchor[axis] + 0.5f) * static_cast<float>(resolution) - 0.5f;
  return MirrorPlane{axis, static_cast<int>(std::lround(2.0f * voxel)), 0.0f};
}
}  // namespace

std::vector<ExtractedPoint> completeMirrorPairs(const PredictedField& field,
                                                const std::vector<ExtractedPoint>& points,
                                                const ExtractionSettings& extraction,
                                                const MirrorPairSettings& settings) {
  if (points.empty() || field.voxels.empty() || field.resolution <= 0) return points;
  const DenseField dense(field.voxels, field.resolution);
  const auto plane = bestMirrorPlane(field.voxels, field.resolution, dense, settings.minSymmetry);
  if (!plane) return points;
  std::vector<ExtractedPoint> out;
  for (const auto& p : points) {
    out.push_back(p);
    if (auto twin = twinAcross(*plane, p, field, dense, points, out, extraction.nmsRadius,
                               extraction, settings))
      out.push_back(*twin);
  }
  return out;
}

std::vector<ExtractedPoint> completeAnchoredPairs(const PredictedField& field,
                                                  const std::vector<ExtractedPoint>& points,
                                                  const std::vector<Eigen::Vector3f>& anchors,
                                                  const ExtractionSettings& extraction,
                                                  const MirrorPairSettings& settings) {
  if (points.empty() || anchors.empty() || field.voxels.empty() || field.resolution <= 0)
    return points;
  const DenseField dense(field.voxels, field.resolution);
  const float voxel = 1.0f / static_cast<float>(field.resolution);
  const float reach = static_cast<float>(settings.anchorRadiusVoxels) * voxel;
  // The two handles of a mixer sit closer together than the count's suppression radius allows
  // for separate instances; the mirror across the spout is the evidence that they are two.
  const float separation =
      std::min(extraction.nmsRadius, static_cast<float>(settings.anchoredSeparationVoxels) * voxel);
  std::vector<ExtractedPoint> out;
  for (const auto& p : points) {
    out.push_back(p);
    const Eigen::Vector3f* nearest = nullptr;
    float nearestDistance = reach;
    for (const auto& a : anchors) {
      const float d = (a - p.position).head<2>().norm();
      if (d <= nearestDistance) nearest = &a, nearestDistance = d;
    }
    if (!nearest) continue;
    // The spout reaches out along the mixer's plane, which may lie along either horizontal
    // axis: of the planes that put the image off the point and about which the spout's own
    // neighbourhood is symmetric (not the plane across its reach, which mirrors a handle behind
    // the spout to the basin in front of it), the one whose image of the point's neighbourhood
    // matches better.
    const VoxelIndex at = voxelContaining(p.position, field.resolution);
    const VoxelIndex spout = voxelContaining(*nearest, field.resolution);
    const int tolerance = std::max(settings.matchToleranceVoxels, 0);
    std::optional<MirrorPlane> plane;
    float planeMatch = -1.0f;
    for (int axis = 0; axis < 2; ++axis) {
      const MirrorPlane candidate = planeThrough(*nearest, axis, field.resolution);
      if ((candidate.mirror(p.position, field.resolution) - p.position).norm() <= separation ||
          localMatch(dense, spout, candidate, settings.neighbourhoodVoxels, tolerance) <
              settings.minLocalMatch)
        continue;
      const float match = localMatch(dense, at, candidate, settings.neighbourhoodVoxels, tolerance);
      if (match > planeMatch) plane = candidate, planeMatch = match;
    }
    if (!plane) continue;
    auto twin = twinAcross(*plane, p, field, dense, points, out, separation, extraction, settings);
    if (twin && !occupiedBetween(dense, p.position, twin->position, field.resolution))
      out.push_back(*twin);
  }
  return out;
}

}  // namespace sagrid
