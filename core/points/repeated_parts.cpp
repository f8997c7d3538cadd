#include "core/points/repeated_parts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/geometry/part_rows.h"
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
    if ((settings.roundFlatSeeds && !isRoundFlatPart(parts[p])) || copies.of(p).empty()) continue;
    if (!at.seed) {
      at.seed = p;
      continue;
    }
    const ConnectedPart& seed = parts[*at.seed];
    // Two knobs of a row both within touch: the nearer one.
    const bool better = congruentParts(seed, parts[p], settings.congruenceTolerance)
                            ? (parts[p].centroid - point).norm() < (seed.centroid - point).norm()
                            : parts[p].area > seed.area;
    if (better) at.seed = p;
  }
  return at;
}

// A part that can be a whole knob (RepeatedPartSettings::snapPartVoxels).
bool isKnobPart(const ConnectedPart& part, float voxel, const RepeatedPartSettings& settings) {
  return settings.snapPartVoxels > 0 &&
         part.box.sizes().maxCoeff() >= settings.snapPartVoxels * voxel;
}

// The nearest small part within `reach` of `point` (box distance) where the field is at most
// `maxDistance` and `accepts` holds (given the part and its number of copies).
template <typename Accepts>
std::optional<std::size_t> nearbyPart(const Eigen::Vector3f& point,
                                      const std::vector<ConnectedPart>& parts,
                                      const PartCopies& copies, float reach, float maxDistance,
                                      const PredictedField& field, const DenseField& dense,
                                      const RepeatedPartSettings& settings, Accepts accepts) {
  std::optional<std::size_t> best;
  float bestGap = reach;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const float gap = parts[p].box.exteriorDistance(point);
    if (!isSmallPart(parts[p], settings.contact.maxPartDiagonal) || gap > bestGap) continue;
    const float d = nearbyDistance(
        field, dense, voxelContaining(parts[p].centroid, field.resolution), kFieldRadius);
    if (!std::isfinite(d) || d > maxDistance || !accepts(parts[p], copies.of(p).size())) continue;
    best = p, bestGap = gap;
  }
  return best;
}

// Where the point at `offset` from `part`'s centroid goes on `copy`; on a copy scaled from it
// (not congruent within `tolerance`), the offset scales with it.
Eigen::Vector3f pointOnCopy(const ConnectedPart& part, const ConnectedPart& copy,
                            Eigen::Vector3f offset, float tolerance) {
  const float scale =
      congruentParts(part, copy, tolerance)
          ? 1.0f
          : similarityScale(part, copy, tolerance, std::numeric_limits<float>::max())
                .value_or(1.0f);
  offset *= scale;
  const Eigen::Vector3f step = copy.centroid - part.centroid;
  const float size = scale * part.box.diagonal().norm();
  const bool moved =
      (scale * part.box.sizes() - copy.box.sizes()).cwiseAbs().maxCoeff() <= tolerance * size;
  if (moved || step.norm() <= 0.0f) return copy.centroid + offset;
  const Eigen::Vector3f n = step.normalized();
  return copy.centroid + offset - 2.0f * offset.dot(n) * n;
}
}  // namespace

bool isRoundFlatPart(const ConnectedPart& part) {
  const Eigen::Vector3f size = part.box.sizes();
  const float wide = std::max(size.x(), size.y()), narrow = std::min(size.x(), size.y());
  return wide > 0 && wide - narrow <= kRoundShare * wide && size.z() <= kFlatShare * narrow;
}

std::vector<ExtractedPoint> completeRepeatedParts(const PredictedField& field,
                                                  const std::vector<ExtractedPoint>& points,
                                                  const std::vector<ConnectedPart>& parts,
                                                  const ExtractionSettings& extraction,
                                                  const RepeatedPartSettings& settings,
                                                  const std::vector<Eigen::Vector3f>& occupied) {
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
  const PartCopies copies(parts, settings.congruenceTolerance, settings.maxCopyScale);
  // Scaled copies, of which those on a sure row's line continue it (rowContinuationScale); only
  // where that can happen.
  const bool continuesRows = settings.sureKnobRow > 0 && settings.rowContinuationScale > 1.0f;
  std::optional<PartCopies> scaledCopies;
  if (continuesRows)
    scaledCopies.emplace(parts, settings.congruenceTolerance,
                         std::max(settings.maxCopyScale, settings.rowContinuationScale));
  const auto isPair = [](const ConnectedPart&, std::size_t n) { return n == 1; };
  const auto isKnobRow = [&](const ConnectedPart& part, std::size_t n) {
    return n >= 1 && isKnobPart(part, voxel, settings);
  };
  const auto isSureKnobRow = [&](const ConnectedPart& part, std::size_t n) {
    return static_cast<int>(n) + 1 >= settings.sureKnobRow && isKnobPart(part, voxel, settings);
  };
  std::vector<ExtractedPoint> out = points;
  if (settings.snapPartVoxels > 0) {
    for (auto& p : out) {
      const PartsAtPoint at = partsAt(p.position, parts, copies, touch, settings);
      std::optional<std::size_t> knob;
      if (at.seed && isKnobPart(parts[*at.seed], voxel, settings))
        knob = at.seed;
      else if (!at.onSmallPart && pairReach > 0) {
        knob = nearbyPart(p.position, parts, copies, pairReach,
                          p.distance + settings.maxDistanceAbovePoint, field, dense, settings,
                          isKnobRow);
        if (!knob && settings.sureKnobRow > 0)
          knob = nearbyPart(p.position, parts, copies, pairReach,
                            std::numeric_limits<float>::infinity(), field, dense, settings,
                            isSureKnobRow);
      }
      if (knob) p.position = parts[*knob].box.center();
    }
  }
  const std::size_t given = out.size();  // the points added below get no copies of their own
  for (std::size_t i = 0; i < given; ++i) {
    ExtractedPoint p = out[i];
    const PartsAtPoint at = partsAt(p.position, parts, copies, touch, settings);
    auto seed = at.seed;
    if (!seed && !at.onSmallPart && pairReach > 0) {
      seed =
          nearbyPart(p.position, parts, copies, pairReach,
                     p.distance + settings.maxDistanceAbovePoint, field, dense, settings, isPair);
      if (seed) out[i].position = p.position = parts[*seed].centroid;
    }
    if (!seed) continue;
    const ConnectedPart& part = parts[*seed];
    const Eigen::Vector3f offset = p.position - part.centroid;
    const std::vector<std::size_t> family = copies.familyOf(*seed);
    // A knob's copies in a row tighter than separationVoxels: their spacing alone.
    const float least = isKnobPart(part, voxel, settings)
                            ? 0.0f
                            : static_cast<float>(settings.separationVoxels) * voxel;
    // A point on `copy` (of the family, or continuing its row) unless one is there; with
    // `fieldDecides`, only where the field is low enough.
    const auto addOnCopy = [&](std::size_t q, bool fieldDecides) {
      const ConnectedPart& copy = parts[q];
      const Eigen::Vector3f onCopy = pointOnCopy(part, copy, offset, settings.congruenceTolerance);
      const float apart =
          settings.separationBySpacing
              ? std::max(least, std::min(separation,
                                         kSpacingShare * nearestCentroidDistance(q, family, parts)))
              : separation;
      const bool taken =
          std::any_of(out.begin(), out.end(),
                      [&](const ExtractedPoint& o) {
                        return (o.position - onCopy).norm() <= apart ||
                               copy.box.exteriorDistance(o.position) <= touch;
                      }) ||
          std::any_of(occupied.begin(), occupied.end(), [&](const Eigen::Vector3f& o) {
            return copy.box.exteriorDistance(o) <= touch;
          });
      if (taken) return;
      const float distance =
          nearbyDistance(field, dense, voxelContaining(onCopy, field.resolution), kFieldRadius);
      if (!std::isfinite(distance) || (fieldDecides && settings.maxDistanceAbovePoint >= 0 &&
                                       distance > p.distance + settings.maxDistanceAbovePoint))
        return;
      ExtractedPoint added;
      added.position = onCopy;
      added.distance = distance;
      added.confidence = confidenceOf(distance, extraction);
      out.push_back(added);
    };
    for (std::size_t q : family)
      if (q != *seed) addOnCopy(q, true);
    if (!continuesRows || static_cast<int>(family.size()) < settings.sureKnobRow ||
        !isKnobPart(part, voxel, settings))
      continue;
    const auto row = partRow(family, parts, kRowLineShare);
    if (!row) continue;
    std::vector<std::size_t> scaled;
    for (std::size_t q : scaledCopies->of(*seed))
      if (std::find(family.begin(), family.end(), q) == family.end() &&
          isSmallPart(parts[q], settings.contact.maxPartDiagonal))
        scaled.push_back(q);
    for (std::size_t q : rowContinuations(*row, scaled, parts, kRowLineShare, kRowReachSpacings))
      addOnCopy(q, false);
  }
  return out;
}

}  // namespace sagrid
