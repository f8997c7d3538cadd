#include "core/points/point_candidates.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/geometry/connected_parts.h"
#include "core/geometry/points_on_copies.h"
#include "core/grid/voxel_grid.h"

namespace sagrid {

namespace {

enum Feature {
  kDistance,
  kDistanceAboveBest,
  kDistanceRank,
  kBasinDepth,
  kKept,
  kFieldMinimum,
  kPartCentroid,
  kHeight,
  kRadial,
  kEdge,
  kCentreLine,
  kOnPart,
  kPartSize,
  kPartFlatness,
  kPartRoundness,
  kPartCopies,
  kPartRoundFlat,
  kKeptCount,
  kNearestKept,
  kCrowding,
  kBestKept,
  kFacingUp,
  kSurfaceDepth,
  kPartByMaterial,
  kPartByCrease,
  kOtherField,
  kOtherClaim,
  kOpenness,
  kClearBelow,
  kClearAbove,
  kFeatureCount
};

// Basin depths and distances to other points are capped where they stop telling anything apart.
constexpr float kDepthCap = 0.2f, kNearCap = 0.3f, kCrowdRadius = 0.08f;
// Free distances straight down and up are capped at half the object (beyond, all is open).
constexpr float kClearCap = 0.5f;
// Parts up to this box diagonal give candidates: larger than the passes' small parts
// (kSmallPartDiagonal), as a range's burner grate can be.
constexpr float kCandidatePartDiagonal = 0.35f;

// The smallest predicted distance among occupied voxels within `reach` voxels of a point; the
// field's largest where none is occupied there.
class FieldLookup {
 public:
  explicit FieldLookup(const PredictedField& field)
      : m_resolution(field.resolution),
        m_dense(static_cast<std::size_t>(field.resolution) * field.resolution * field.resolution,
                std::numeric_limits<float>::infinity()) {
    for (std::size_t v = 0; v < field.voxels.size(); ++v) {
      m_dense[linear(field.voxels[v])] = field.distances[v];
      m_largest = std::max(m_largest, field.distances[v]);
    }
  }
  float near(const Eigen::Vector3f& point, int reach) const {
    const VoxelIndex c = voxelContaining(point, m_resolution);
    float best = std::numeric_limits<float>::infinity();
    for (int di = -reach; di <= reach; ++di)
      for (int dj = -reach; dj <= reach; ++dj)
        for (int dk = -reach; dk <= reach; ++dk) {
          const VoxelIndex v{c.i + di, c.j + dj, c.k + dk};
          if (v.i < 0 || v.j < 0 || v.k < 0 || v.i >= m_resolution || v.j >= m_resolution ||
              v.k >= m_resolution)
            continue;
          best = std::min(best, m_dense[linear(v)]);
        }
    return std::isfinite(best) ? best : m_largest;
  }

 private:
  std::size_t linear(const VoxelIndex& v) const {
    return (static_cast<std::size_t>(v.i) * m_resolution + v.j) * m_resolution + v.k;
  }
  int m_resolution;
  std::vector<float> m_dense;
  float m_largest = 0;
};

struct Seed {
  Eigen::Vector3f position;
  bool kept = false, minimum = false, part = false;
  float basinDepth = 0;
};

// Adds a seed, or merges it into an earlier one closer than `merge`.
void addSeed(std::vector<Seed>& seeds, const Seed& seed, float merge) {
  for (Seed& s : seeds)
    if ((s.position - seed.position).norm() < merge) {
      s.kept |= seed.kept;
      s.minimum |= seed.minimum;
      s.part |= seed.part;
      s.basinDepth = std::max(s.basinDepth, seed.basinDepth);
      return;
    }
  seeds.push_back(seed);
}

// Per seed, the seeds at its place on each copy of the part it lies on (its offset from the
// part's centroid kept; the nearest seed closer than `merge` there, none where there is none).
// Adding a candidate at every such place instead was tried: more candidates, worse decisions
// leave one source out (0.589 -> 0.597 edits per hand point without taking copies).
std::vector<std::vector<std::size_t>> copyLinks(const std::vector<Seed>& seeds,
                                                const std::vector<ConnectedPart>& parts,
                                                const PartCopies& copies, float touch,
                                                float merge) {
  std::vector<std::vector<std::size_t>> links(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const auto on = partAt(seeds[s].position, parts, touch, kCandidatePartDiagonal);
    if (!on) continue;
    const auto onCopies = placesOnCopies(seeds[s].position, *on, parts, copies);
    if (onCopies.empty() || onCopies.size() > kMaxCandidateCopies) continue;
    std::vector<std::size_t> places;
    const auto addPlace = [&](std::size_t i) {
      if (std::find(places.begin(), places.end(), i) == places.end()) places.push_back(i);
    };
    for (const Eigen::Vector3f& place : onCopies) {
      float nearest = merge;
      std::size_t at = seeds.size();
      for (std::size_t o = 0; o < seeds.size(); ++o)
        if (const float d = (seeds[o].position - place).norm(); d < nearest) nearest = d, at = o;
      if (at < seeds.size()) addPlace(at);
    }
    addPlace(s);
    for (std::size_t i : places)
      for (std::size_t j : places)
        if (i != j && std::find(links[i].begin(), links[i].end(), j) == links[i].end())
          links[i].push_back(j);
  }
  return links;
}

float share(float value, float lo, float hi) {
  return hi > lo ? std::clamp((value - lo) / (hi - lo), 0.0f, 1.0f) : 0.5f;
}

}  // namespace

const std::vector<std::string>& candidateFeatureNames() {
  // clang-format off
  static const std::vector<std::string> names = {
      "distance",       "distance_above_best", "distance_rank",  "basin_depth",
      "kept",           "field_minimum",       "part_centroid",  "height",
      "radial",         "edge",                "centre_line",    "on_part",
      "part_size",      "part_flatness",       "part_roundness", "part_copies",
      "part_round_flat", "kept_count",         "nearest_kept",   "crowding",
      "best_kept",      "facing_up",           "surface_depth",  "part_by_material",
      "part_by_crease", "other_field",     "other_claim",    "openness",
      "clear_below",    "clear_above"};
  // clang-format on
  return names;
}

std::size_t candidateFeatureIndex(const std::string& name) {
  const auto& names = candidateFeatureNames();
  const auto at = std::find(names.begin(), names.end(), name);
  if (at == names.end()) throw InvalidArgument("no candidate feature named " + name);
  return static_cast<std::size_t>(at - names.begin());
}

std::vector<PointCandidate> pointCandidates(const PredictedField& field,
                                            const std::vector<ExtractedPoint>& kept,
                                            const std::vector<ConnectedPart>& parts,
                                            const SurfaceContactAt& contact,
                                            const std::vector<const PredictedField*>& others,
                                            std::size_t maxMinima) {
  if (field.voxels.empty() || field.voxels.size() != field.distances.size()) return {};
  const FieldLookup lookup(field);
  std::vector<std::pair<FieldLookup, float>> otherLookups;  // each with its best distance
  for (const PredictedField* other : others)
    if (other && !other->voxels.empty() && other->voxels.size() == other->distances.size())
      otherLookups.emplace_back(FieldLookup(*other),
                                *std::min_element(other->distances.begin(), other->distances.end()));
  const float voxel = 1.0f / static_cast<float>(field.resolution);
  const float merge = 1.5f * voxel;

  std::vector<Seed> seeds;
  for (const ExtractedPoint& p : kept) addSeed(seeds, {p.position, true, false, false, 0}, merge);
  const auto minima = fieldMinima(field);
  for (std::size_t i = 0; i < minima.size() && i < maxMinima; ++i)
    addSeed(seeds,
            {voxelCenter(field.voxels[minima[i].voxel], field.resolution), false, true, false,
             std::min(minima[i].persistence, kDepthCap)},
            merge);
  // A part's centroid (a knob, a handle) and the middle of its top (a burner's grate or ring,
  // whose centroid may lie in the air between its bars).
  for (const ConnectedPart& part : parts)
    if (part.triangles >= kMinInstanceTriangles && isSmallPart(part, kCandidatePartDiagonal)) {
      addSeed(seeds, {part.centroid, false, false, true, 0}, merge);
      const Eigen::Vector3f top(part.box.center().x(), part.box.center().y(), part.box.max().z());
      addSeed(seeds, {top, false, false, true, 0}, merge);
    }
  const PartCopies copies(parts, kCopyTolerance);
  const auto links = copyLinks(seeds, parts, copies, PartContact{}.touchVoxels * voxel, merge);

  Eigen::AlignedBox3f box;
  float best = std::numeric_limits<float>::infinity();
  for (std::size_t v = 0; v < field.voxels.size(); ++v) {
    box.extend(voxelCenter(field.voxels[v], field.resolution));
    best = std::min(best, field.distances[v]);
  }
  const Eigen::Vector3f centre = box.center(), half = box.sizes() / 2;
  const float objectDiagonal = std::max(box.diagonal().norm(), voxel);

  std::vector<PointCandidate> out(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    out[s].position = seeds[s].position;
    out[s].distance = lookup.near(seeds[s].position, 1);
    out[s].kept = seeds[s].kept;
    out[s].copies = links[s];
  }
  std::vector<float> sorted;
  for (const auto& c : out) sorted.push_back(c.distance);
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const Seed& seed = seeds[s];
    const Eigen::Vector3f& p = seed.position;
    std::vector<float> f(kFeatureCount, 0.0f);
    f[kDistance] = out[s].distance;
    f[kDistanceAboveBest] = out[s].distance - best;
    const auto rank =
        std::lower_bound(sorted.begin(), sorted.end(), out[s].distance) - sorted.begin();
    f[kDistanceRank] = sorted.size() > 1 ? static_cast<float>(rank) / (sorted.size() - 1) : 0;
    f[kBasinDepth] = seed.basinDepth / kDepthCap;
    f[kKept] = seed.kept;
    f[kFieldMinimum] = seed.minimum;
    f[kPartCentroid] = seed.part;
    f[kHeight] = share(p.z(), box.min().z(), box.max().z());
    const Eigen::Vector2f offset = (p - centre).head<2>();
    f[kRadial] = std::min(offset.norm() / std::max(half.head<2>().norm(), voxel), 1.0f);
    const float ex = std::abs(offset.x()) / std::max(half.x(), voxel);
    const float ey = std::abs(offset.y()) / std::max(half.y(), voxel);
    f[kEdge] = std::min(std::max(ex, ey), 1.0f);
    f[kCentreLine] = std::min(std::min(ex, ey), 1.0f);
    if (const auto on = partAt(p, parts, PartContact{}.touchVoxels * voxel, kSmallPartDiagonal)) {
      const ConnectedPart& part = parts[*on];
      const float largest = std::max(part.spread.x(), 1e-6f);
      f[kOnPart] = 1;
      f[kPartSize] = part.box.diagonal().norm() / objectDiagonal;
      f[kPartFlatness] = part.spread.z() / largest;
      f[kPartRoundness] = part.spread.y() / largest;
      f[kPartCopies] =
          std::min(std::log1p(static_cast<float>(copies.of(*on).size())) / std::log(9.0f), 1.0f);
      f[kPartRoundFlat] = isRoundFlatPart(part);
      f[kPartByMaterial] = part.byMaterial;
      f[kPartByCrease] = part.byCrease;
    }
    f[kKeptCount] = std::log1p(static_cast<float>(kept.size())) / std::log(9.0f);
    float nearestKept = kNearCap;
    int crowd = 0;
    for (std::size_t o = 0; o < seeds.size(); ++o) {
      if (o == s) continue;
      const float d = (seeds[o].position - p).norm();
      if (seeds[o].kept) nearestKept = std::min(nearestKept, d);
      if (d < kCrowdRadius && out[o].distance < out[s].distance) ++crowd;
    }
    f[kNearestKept] = nearestKept / kNearCap;
    f[kCrowding] = std::min(crowd / 5.0f, 1.0f);
    f[kBestKept] = !kept.empty() && (kept.front().position - p).norm() < merge;
    const SurfaceContact surface = contact(p);
    f[kFacingUp] = surface.normal.z();
    f[kSurfaceDepth] = std::min(surface.depth / kNearCap, 1.0f);
    f[kOpenness] = surface.openness;
    f[kClearBelow] = std::min(surface.below / kClearCap, 1.0f);
    f[kClearAbove] = std::min(surface.above / kClearCap, 1.0f);
    f[kOtherField] = 1;
    for (const auto& [other, otherBest] : otherLookups)
      f[kOtherField] = std::min(f[kOtherField], (other.near(p, 1) - otherBest) / kDepthCap);
    f[kOtherClaim] = std::clamp(f[kOtherField] - f[kDistanceAboveBest] / kDepthCap, -1.0f, 1.0f);
    out[s].features = std::move(f);
  }
  return out;
}

}  // namespace sagrid
