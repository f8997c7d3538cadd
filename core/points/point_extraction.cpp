#include "core/points/point_extraction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "core/common/error.h"

namespace sagrid {

float confidenceOf(float distance, const ExtractionSettings& s) {
  return std::exp(-std::max(0.0f, distance) / std::max(1e-6f, s.confidenceScale));
}

namespace {

void validate(const PredictedField& field) {
  if (field.voxels.empty())
    throw InvalidArgument("point extraction: the object has no occupied voxels");
  if (field.voxels.size() != field.distances.size())
    throw InvalidArgument("point extraction: " + std::to_string(field.distances.size()) +
                          " distances for " + std::to_string(field.voxels.size()) + " voxels");
}

ExtractedPoint pointAt(const PredictedField& field, std::size_t v, const ExtractionSettings& s) {
  ExtractedPoint p;
  p.position = voxelCenter(field.voxels[v], field.resolution);
  if (s.refineVoxels > 0) {
    const VoxelIndex& c = field.voxels[v];
    const float r2 = s.refineVoxels * s.refineVoxels;
    const float tau = 0.5f / static_cast<float>(field.resolution);
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    float mass = 0;
    for (std::size_t u = 0; u < field.voxels.size(); ++u) {
      const VoxelIndex& q = field.voxels[u];
      const float di = static_cast<float>(q.i - c.i), dj = static_cast<float>(q.j - c.j),
                  dk = static_cast<float>(q.k - c.k);
      if (di * di + dj * dj + dk * dk > r2) continue;
      const float w = std::exp(-(field.distances[u] - field.distances[v]) / tau);
      sum += w * voxelCenter(q, field.resolution);
      mass += w;
    }
    if (mass > 0) p.position = sum / mass;
  }
  p.distance = field.distances[v];
  p.confidence = confidenceOf(p.distance, s);
  return p;
}

std::vector<Eigen::Vector3f> centres(const PredictedField& field,
                                     const std::vector<std::size_t>& ids) {
  std::vector<Eigen::Vector3f> out;
  out.reserve(ids.size());
  for (auto v : ids) out.push_back(voxelCenter(field.voxels[v], field.resolution));
  return out;
}

// k-means with k-means++ seeding; returns assignments of the best of several restarts.
std::vector<int> kMeans(const std::vector<Eigen::Vector3f>& points,
                        const std::vector<float>& weights, int k, unsigned seed) {
  const std::size_t n = points.size();
  std::mt19937 rng(seed);
  std::vector<int> best(n, 0);
  double bestInertia = std::numeric_limits<double>::max();
  for (int restart = 0; restart < 8; ++restart) {
    std::vector<Eigen::Vector3f> centers;
    centers.push_back(points[std::uniform_int_distribution<std::size_t>(0, n - 1)(rng)]);
    std::vector<double> d2(n);
    while (static_cast<int>(centers.size()) < k) {
      double total = 0;
      for (std::size_t i = 0; i < n; ++i) {
        double m = std::numeric_limits<double>::max();
        for (const auto& c : centers)
          m = std::min(m, static_cast<double>((points[i] - c).squaredNorm()));
        d2[i] = m * weights[i];
        total += d2[i];
      }
      if (total <= 0) break;
      double pick = std::uniform_real_distribution<double>(0, total)(rng);
      std::size_t chosen = n - 1;
      for (std::size_t i = 0; i < n; ++i) {
        pick -= d2[i];
        if (pick <= 0) {
          chosen = i;
          break;
        }
      }
      centers.push_back(points[chosen]);
    }
    std::vector<int> assign(n, 0);
    for (int iteration = 0; iteration < 50; ++iteration) {
      bool changed = false;
      for (std::size_t i = 0; i < n; ++i) {
        int arg = 0;
        float m = std::numeric_limits<float>::max();
        for (std::size_t c = 0; c < centers.size(); ++c) {
          const float d = (points[i] - centers[c]).squaredNorm();
          if (d < m) m = d, arg = static_cast<int>(c);
        }
        if (assign[i] != arg) {
          changed = true;
          assign[i] = arg;
        }
      }
      std::vector<Eigen::Vector3f> sum(centers.size(), Eigen::Vector3f::Zero());
      std::vector<float> mass(centers.size(), 0.0f);
      for (std::size_t i = 0; i < n; ++i)
        sum[assign[i]] += weights[i] * points[i], mass[assign[i]] += weights[i];
      for (std::size_t c = 0; c < centers.size(); ++c)
        if (mass[c] > 0) centers[c] = sum[c] / mass[c];
      if (!changed && iteration > 0) break;
    }
    double inertia = 0;
    for (std::size_t i = 0; i < n; ++i)
      inertia += weights[i] * (points[i] - centers[assign[i]]).squaredNorm();
    if (inertia < bestInertia) bestInertia = inertia, best = assign;
  }
  return best;
}

}  // namespace

ExtractedPoint argminPoint(const PredictedField& field, const ExtractionSettings& settings) {
  validate(field);
  const auto it = std::min_element(field.distances.begin(), field.distances.end());
  return pointAt(field, static_cast<std::size_t>(it - field.distances.begin()), settings);
}

std::vector<FieldMinimum> fieldMinima(const PredictedField& field) {
  validate(field);
  const std::size_t n = field.voxels.size();
  const std::size_t r = static_cast<std::size_t>(field.resolution);
  std::vector<std::int32_t> slot(r * r * r, -1);
  auto linear = [&](const VoxelIndex& v) { return (v.i * r + v.j) * r + v.k; };
  for (std::size_t v = 0; v < n; ++v) slot[linear(field.voxels[v])] = static_cast<std::int32_t>(v);
  // Voxels join the sublevel set in order of distance (plateaus: lower index first), so a voxel
  // none of whose neighbours joined before it is exactly a local minimum of localMinima.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return field.distances[a] < field.distances[b];
  });
  std::vector<std::size_t> rank(n);
  for (std::size_t i = 0; i < n; ++i) rank[order[i]] = i;
  constexpr std::size_t kOutside = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> parent(n, kOutside), minimumOf(n, kOutside);
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<FieldMinimum> minima;
  std::vector<std::size_t> slotOfMinimum(n, kOutside);
  for (std::size_t x : order) {
    const VoxelIndex& p = field.voxels[x];
    std::size_t root = kOutside;
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c) {
          const VoxelIndex q{p.i + a, p.j + b, p.k + c};
          if ((a == 0 && b == 0 && c == 0) || q.i < 0 || q.j < 0 || q.k < 0 ||
              q.i >= field.resolution || q.j >= field.resolution || q.k >= field.resolution)
            continue;
          const std::int32_t s = slot[linear(q)];
          if (s < 0 || parent[s] == kOutside) continue;
          const std::size_t other = find(static_cast<std::size_t>(s));
          if (root == kOutside) {
            root = other;
            continue;
          }
          if (other == root) continue;
          // Two basins meet at this voxel's level: the one with the worse minimum ends.
          std::size_t keep = root, end = other;
          if (rank[minimumOf[end]] < rank[minimumOf[keep]]) std::swap(keep, end);
          minima[slotOfMinimum[minimumOf[end]]].persistence =
              field.distances[x] - field.distances[minimumOf[end]];
          parent[end] = keep;
          root = keep;
        }
    if (root == kOutside) {  // a new basin
      parent[x] = minimumOf[x] = x;
      slotOfMinimum[x] = minima.size();
      minima.push_back({x, std::numeric_limits<float>::infinity()});
    } else {
      parent[x] = root;
    }
  }
  return minima;  // joined in distance order: best first
}

std::vector<std::size_t> localMinima(const PredictedField& field) {
  std::vector<std::size_t> out;
  for (const auto& m : fieldMinima(field)) out.push_back(m.voxel);
  return out;
}

namespace {

// The automatic count's rule over candidate minima, best first: the best is always kept; then
// minima within the distance threshold whose basin is deep enough and that lie at least the
// suppression radius from every kept one. `positionOf(i)` is asked only for candidates that pass
// the threshold and depth tests.
template <typename PositionOf>
std::vector<std::size_t> keptMinima(const std::vector<float>& distances,
                                    const std::vector<float>& persistences,
                                    const ExtractionSettings& s, PositionOf&& positionOf) {
  std::vector<std::size_t> kept;
  std::vector<Eigen::Vector3f> keptAt;
  if (distances.empty()) return kept;
  const float threshold =
      s.maxDistanceAboveBest ? distances.front() + s.maxDistance : s.maxDistance;
  for (std::size_t i = 0; i < distances.size(); ++i) {
    if (!kept.empty() && distances[i] > threshold) break;  // sorted by distance
    if (!kept.empty() && persistences[i] < s.minPersistence) continue;
    const Eigen::Vector3f p = positionOf(i);
    bool suppressed = false;
    for (const auto& k : keptAt) suppressed |= (k - p).norm() < s.nmsRadius;
    if (suppressed) continue;
    kept.push_back(i);
    keptAt.push_back(p);
  }
  return kept;
}

}  // namespace

std::vector<ExtractedPoint> autoCountPoints(const PredictedField& field,
                                            const ExtractionSettings& settings) {
  const std::vector<FieldMinimum> minima = fieldMinima(field);
  std::vector<float> distances, persistences;
  for (const auto& m : minima) {
    distances.push_back(field.distances[m.voxel]);
    persistences.push_back(m.persistence);
  }
  std::vector<ExtractedPoint> points(minima.size());
  const auto kept = keptMinima(distances, persistences, settings, [&](std::size_t i) {
    points[i] = pointAt(field, minima[i].voxel, settings);
    return points[i].position;
  });
  std::vector<ExtractedPoint> out;
  for (std::size_t i : kept) out.push_back(points[i]);
  return out;
}

std::vector<ExtractedPoint> kMeansPoints(const PredictedField& field, int count,
                                         const ExtractionSettings& settings) {
  validate(field);
  if (count < 1) throw InvalidArgument("point extraction: instance count must be at least 1");
  if (count == 1) return {argminPoint(field, settings)};
  // Threshold: low enough to separate instances, high enough that each instance has voxels —
  // at least a few voxels' worth, and at least the count-th best separated minimum.
  std::vector<std::size_t> order(field.voxels.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return field.distances[a] < field.distances[b]; });
  const float voxel = 1.0f / static_cast<float>(field.resolution);
  const float best = field.distances[order.front()];
  float threshold =
      std::max(settings.maxDistanceAboveBest ? best + settings.maxDistance : settings.maxDistance,
               2.5f * voxel);
  // The count is known: every separated minimum competes, shallow basins too (the depth test
  // is the automatic count's, not this one's).
  ExtractionSettings relaxed = settings;
  relaxed.maxDistance = std::numeric_limits<float>::max();
  relaxed.maxDistanceAboveBest = false;
  relaxed.minPersistence = 0.0f;
  const auto minima = autoCountPoints(field, relaxed);
  if (static_cast<int>(minima.size()) >= count)
    threshold = std::max(threshold, minima[count - 1].distance + 1.5f * voxel);
  std::vector<std::size_t> low;
  for (std::size_t v : order) {
    if (field.distances[v] > threshold && low.size() >= static_cast<std::size_t>(4 * count)) break;
    low.push_back(v);
  }
  const int k = std::min<int>(count, static_cast<int>(low.size()));
  const auto points = centres(field, low);
  std::vector<float> weights;
  for (auto v : low) weights.push_back(confidenceOf(field.distances[v], settings) + 1e-3f);
  const auto assign = kMeans(points, weights, k, 12345u);
  std::vector<ExtractedPoint> out(k);
  std::vector<float> mass(k, 0.0f);
  for (auto& p : out) p.distance = std::numeric_limits<float>::max(), p.position.setZero();
  for (std::size_t i = 0; i < low.size(); ++i) {
    auto& p = out[assign[i]];
    p.position += weights[i] * points[i];
    mass[assign[i]] += weights[i];
    p.distance = std::min(p.distance, field.distances[low[i]]);
  }
  std::vector<ExtractedPoint> result;
  for (int c = 0; c < k; ++c) {
    if (mass[c] <= 0) continue;
    out[c].position /= mass[c];
    out[c].confidence = confidenceOf(out[c].distance, settings);
    result.push_back(out[c]);
  }
  std::sort(result.begin(), result.end(), [](const ExtractedPoint& a, const ExtractedPoint& b) {
    return a.distance < b.distance;
  });
  return result;
}

ExtractionSettings calibrateExtraction(const std::vector<PredictedField>& fields,
                                       const ExtractionCost& cost, const ExtractionSettings& base) {
  ExtractionSettings best = base;
  if (fields.empty()) return best;
  double bestCost = std::numeric_limits<double>::max();
  // Minima, their depths and refined positions are computed once; only the filtering depends on
  // the candidates.
  struct Candidates {
    std::vector<float> distances, persistences;
    std::vector<Eigen::Vector3f> positions;
  };
  std::vector<Candidates> candidates;
  for (const auto& f : fields) {
    Candidates c;
    for (const auto& m : fieldMinima(f)) {
      c.distances.push_back(f.distances[m.voxel]);
      c.persistences.push_back(m.persistence);
      c.positions.push_back(pointAt(f, m.voxel, base).position);
    }
    candidates.push_back(std::move(c));
  }
  // Fields averaged over test-time symmetries are smoother than a model's fields on its own
  // training objects: their minima sit higher, hence the larger candidates.
  ExtractionSettings s = base;
  for (bool aboveBest : {false, true})
    for (float persistence : {0.0f, 0.005f, 0.01f, 0.02f, 0.03f, 0.05f})
      for (float maxDistance :
           {0.01f, 0.015f, 0.02f, 0.03f, 0.04f, 0.05f, 0.06f, 0.08f, 0.1f, 0.12f, 0.15f, 0.2f})
        for (float radius : {0.03f, 0.05f, 0.07f, 0.1f, 0.13f, 0.16f, 0.2f, 0.25f, 0.3f}) {
          s.maxDistanceAboveBest = aboveBest;
          s.minPersistence = persistence;
          s.maxDistance = maxDistance;
          s.nmsRadius = radius;
          double total = 0;
          for (std::size_t o = 0; o < fields.size() && total < bestCost; ++o) {
            const Candidates& c = candidates[o];
            std::vector<Eigen::Vector3f> kept;
            for (std::size_t i : keptMinima(c.distances, c.persistences, s,
                                            [&](std::size_t i) { return c.positions[i]; }))
              kept.push_back(c.positions[i]);
            total += cost(o, kept);
          }
          if (total < bestCost) {
            bestCost = total;
            best = s;
          }
        }
  return best;
}

ExtractionSettings calibrateExtraction(const std::vector<PredictedField>& fields,
                                       const std::vector<std::vector<Eigen::Vector3f>>& truths,
                                       const ExtractionSettings& base) {
  if (fields.size() != truths.size()) return base;
  // Right counts first; among equals, the smaller total count difference.
  const double wrongCount = 1e6;
  return calibrateExtraction(
      fields,
      [&](std::size_t o, const std::vector<Eigen::Vector3f>& kept) {
        const double diff = std::abs(static_cast<double>(kept.size()) - truths[o].size());
        return (diff == 0 ? 0.0 : wrongCount) + diff;
      },
      base);
}

}  // namespace sagrid
