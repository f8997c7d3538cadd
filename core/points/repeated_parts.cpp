#include "core/points/repeated_parts.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/points/field_lookup.h"

namespace sagrid {

namespace {
// Where a new point's field is read: the smallest predicted distance within this many voxels.
constexpr int kFieldRadius = 2;

// The small parts whose grown box holds a point: whether there are any, and the one it repeats
// (of those with a copy, the one with the largest area).
struct PartsAtPoint {
  bool onSmallPart = false;
  std::optional<std::size_t> seed;
};
PartsAtPoint partsAt(const Eigen::Vector3f& point, const std::vector<ConnectedPart>& parts,
                     const PartCopies& copies, float touch, const RepeatedPartSettings& settings) {
  PartsAtPoint at;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (!isSmallPart(parts[p], settings.contact.maxPartDiagonal) ||
        parts[p].box.exteriorDistance(point) > touch)
      continue;
    at.onSmallPart = true;
    if ((!at.seed || parts[p].area > parts[*at.seed].area) && !copies.of(p).empty()) at.seed = p;
  }
  return at;
}

// The nearest small part with exactly one copy (a pair) within `reach` of `point` (box distance)
// where the field is at most `maxDistance`.
std::optional<std::size_t> nearbyPairedPart(const Eigen::Vector3f& point,
                                            const std::vector<ConnectedPart>& parts,
                                            const PartCopies& copies, float reach,
                                            float maxDistance, const PredictedField& field,
                                            const DenseField& dense,
                                            const RepeatedPartSettings& settings) {
  std::optional<std::size_t> best;
  float bestGap = reach;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const float gap = parts[p].box.exteriorDistance(point);
    if (!isSmallPart(parts[p], settings.contact.maxPartDiagonal) || gap > bestGap) continue;
    const float d = nearbyDistance(
        field, dense, voxelContaining(parts[p].centroid, field.resolution), kFieldRadius);
    if (!std::isfinite(d) || d > maxDistance || copies.of(p).size() != 1) continue;
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
  const float touch = settings.contact.touchVoxels * voxel;
  // Parts of one instance (the spokes of a cross handle) are copies of one another too: no point
  // within the count's suppression radius of another.
  const float separation =
      std::max(static_cast<float>(settings.separationVoxels) * voxel, extraction.nmsRadius);
  const float pairReach = settings.pairReachVoxels * voxel;
  const PartCopies copies(parts, settings.congruenceTolerance);
  std::vector<ExtractedPoint> out = points;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ExtractedPoint p = points[i];
    const PartsAtPoint at = partsAt(p.position, parts, copies, touch, settings);
    auto seed = at.seed;
    if (!seed && !at.onSmallPart && pairReach > 0) {
      seed = nearbyPairedPart(p.position, parts, copies, pairReach,
                              p.distance + settings.maxDistanceAbovePoint, field, dense, settings);
      if (seed) out[i].position = p.position = parts[*seed].centroid;
    }
    if (!seed) continue;
    const ConnectedPart& part = parts[*seed];
    const Eigen::Vector3f offset = p.position - part.centroid;
    const std::vector<std::size_t> family = copies.familyOf(*seed);
    for (std::size_t q : copies.of(*seed)) {
      const ConnectedPart& copy = parts[q];
      const Eigen::Vector3f onCopy = pointOnCopy(part, copy, offset, settings.congruenceTolerance);
      const float apart =
          settings.separationBySpacing
              ? std::max(
                    static_cast<float>(settings.separationVoxels) * voxel,
                    std::min(separation, kSpacingShare * nearestCentroidDistance(q, family, parts)))
              : separation;
      const bool taken = std::any_of(out.begin(), out.end(), [&](const ExtractedPoint& o) {
        return (o.position - onCopy).norm() <= apart ||
               copy.box.exteriorDistance(o.position) <= touch;
      });
      if (taken) continue;
      const float distance =
          nearbyDistance(field, dense, voxelContaining(onCopy, field.resolution), kFieldRadius);
      if (!std::isfinite(distance) || (settings.maxDistanceAbovePoint >= 0 &&
                                       distance > p.distance + settings.maxDistanceAbovePoint))
        continue;
      ExtractedPoint added;
      added.position = onCopy;
      added.distance = distance;
      added.confidence = confidenceOf(distance, extraction);
      out.push_back(added);
    }
  }
  return out;
}

}  // namespace sagrid
