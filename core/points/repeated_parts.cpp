#include "core/points/repeated_parts.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/points/field_lookup.h"

namespace sagrid {

namespace {
// Where a new point's field is read: the smallest predicted distance within this many voxels.
constexpr int kFieldRadius = 2;

// How many other parts are copies of part p.
int copies(const std::vector<ConnectedPart>& parts, std::size_t p, float tolerance) {
  int n = 0;
  for (std::size_t q = 0; q < parts.size(); ++q)
    n += q != p && congruentParts(parts[p], parts[q], tolerance);
  return n;
}

bool small(const ConnectedPart& part, const RepeatedPartSettings& settings) {
  return !part.box.isEmpty() && part.box.diagonal().norm() <= settings.maxPartDiagonal;
}

// The part `point` lies on, when it has copies: of the small parts whose grown box holds it and
// that have a copy, the one with the largest area.
std::optional<std::size_t> seedPart(const Eigen::Vector3f& point,
                                    const std::vector<ConnectedPart>& parts, float touch,
                                    const RepeatedPartSettings& settings) {
  std::optional<std::size_t> best;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (!small(parts[p], settings) || parts[p].box.exteriorDistance(point) > touch ||
        (best && parts[p].area <= parts[*best].area))
      continue;
    if (copies(parts, p, settings.congruenceTolerance) > 0) best = p;
  }
  return best;
}

// The nearest small part with exactly one copy (a pair) within `reach` of `point` (box distance)
// where the field is at most `maxDistance`.
std::optional<std::size_t> nearbyPairedPart(const Eigen::Vector3f& point,
                                            const std::vector<ConnectedPart>& parts, float reach,
                                            float maxDistance, const PredictedField& field,
                                            const DenseField& dense,
                                            const RepeatedPartSettings& settings) {
  std::optional<std::size_t> best;
  float bestGap = reach;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const float gap = parts[p].box.exteriorDistance(point);
    if (!small(parts[p], settings) || gap > bestGap) continue;
    const float d = nearbyDistance(
        field, dense, voxelContaining(parts[p].centroid, field.resolution), kFieldRadius);
    if (!std::isfinite(d) || d > maxDistance || copies(parts, p, settings.congruenceTolerance) != 1)
      continue;
    best = p, bestGap = gap;
  }
  return best;
}

// Where the point at `offset` from `part`'s centroid goes on `copy`.
Eigen::Vector3f pointOnCopy(const ConnectedPart& part, const ConnectedPart& copy,
                            const Eigen::Vector3f& offset, float tolerance) {
  const Eigen::Vector3f step = copy.centroid - part.centroid;
  const float size = part.box.diagonal().norm();
  const bool moved =
      (part.box.sizes() - copy.box.sizes()).cwiseAbs().maxCoeff() <= tolerance * size;
  if (moved || step.norm() <= 0.0f) return copy.centroid + offset;
  const Eigen::Vector3f n = step.normalized();
  return copy.centroid + offset - 2.0f * offset.dot(n) * n;
}
}  // namespace

std::vector<ExtractedPoint> completeRepeatedParts(const PredictedField& field,
                                                  const std::vector<ExtractedPoint>& points,
                                                  const std::vector<ConnectedPart>& parts,
                                                  const ExtractionSettings& extraction,
                                                  const RepeatedPartSettings& settings) {
  if (points.empty() || parts.empty() || field.voxels.empty() || field.resolution <= 0)
    return points;
  const DenseField dense(field.voxels, field.resolution);
  const float voxel = 1.0f / static_cast<float>(field.resolution);
  const float touch = settings.touchVoxels * voxel;
  // Parts of one instance (the spokes of a cross handle) are copies of one another too: no point
  // within the count's suppression radius of another.
  const float separation =
      std::max(static_cast<float>(settings.separationVoxels) * voxel, extraction.nmsRadius);
  const float pairReach = settings.pairReachVoxels * voxel;
  std::vector<ExtractedPoint> out = points;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ExtractedPoint p = points[i];
    auto seed = seedPart(p.position, parts, touch, settings);
    const bool onSmallPart =
        std::any_of(parts.begin(), parts.end(), [&](const ConnectedPart& part) {
          return small(part, settings) && part.box.exteriorDistance(p.position) <= touch;
        });
    if (!seed && !onSmallPart && pairReach > 0) {
      seed = nearbyPairedPart(p.position, parts, pairReach,
                              p.distance + settings.maxDistanceAbovePoint, field, dense, settings);
      if (seed) out[i].position = p.position = parts[*seed].centroid;
    }
    if (!seed) continue;
    const ConnectedPart& part = parts[*seed];
    const Eigen::Vector3f offset = p.position - part.centroid;
    for (std::size_t q = 0; q < parts.size(); ++q) {
      const ConnectedPart& copy = parts[q];
      if (q == *seed || !congruentParts(part, copy, settings.congruenceTolerance)) continue;
      const Eigen::Vector3f at = pointOnCopy(part, copy, offset, settings.congruenceTolerance);
      const bool taken = std::any_of(out.begin(), out.end(), [&](const ExtractedPoint& o) {
        return (o.position - at).norm() <= separation ||
               copy.box.exteriorDistance(o.position) <= touch;
      });
      if (taken) continue;
      const float distance =
          nearbyDistance(field, dense, voxelContaining(at, field.resolution), kFieldRadius);
      if (!std::isfinite(distance) || (settings.maxDistanceAbovePoint >= 0 &&
                                       distance > p.distance + settings.maxDistanceAbovePoint))
        continue;
      ExtractedPoint added;
      added.position = at;
      added.distance = distance;
      added.confidence =
          std::exp(-std::max(distance, 0.0f) / std::max(extraction.confidenceScale, 1e-6f));
      out.push_back(added);
    }
  }
  return out;
}

}  // namespace sagrid
