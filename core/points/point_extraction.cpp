#include "core/points/point_extraction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "core/common/error.h"

namespace sagrid {
namespace {

void validate(const PredictedField& field) {
  if (field.voxels.empty())
    throw InvalidArgument("point extraction: the object has no occupied voxels");
  if (field.voxels.size() != field.distances.size())
    throw InvalidArgument("point extraction: " + std::to_string(field.distances.size()) +
                          " distances for " + std::to_string(field.voxels.size()) + " voxels");
}

float confidenceOf(float distance, const ExtractionSettings& s) {
  return std::exp(-std::max(0.0f, distance) / std::max(1e-6f, s.confidenceScale));
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

std::vector<std::size_t> localMinima(const PredictedField& field) {
  validate(field);
  const std::size_t r = static_cast<std::size_t>(field.resolution);
  std::vector<std::int32_t> slot(r * r * r, -1);
  auto linear = [&](const VoxelIndex& v) { return (v.i * r + v.j) * r + v.k; };
  for (std::size_t v = 0; v < field.voxels.size(); ++v)
    slot[linear(field.voxels[v])] = static_cast<std::int32_t>(v);
  std::vector<std::size_t> minima;
  for (std::size_t v = 0; v < field.voxels.size(); ++v) {
    const VoxelIndex& p = field.voxels[v];
    const float d = field.distances[v];
    bool isMinimum = true;
    for (int a = -1; a <= 1 && isMinimum; ++a)
      for (int b = -1; b <= 1 && isMinimum; ++b)
        for (int c = -1; c <= 1 && isMinimum; ++c) {
          const VoxelIndex q{p.i + a, p.j + b, p.k + c};
          if ((a == 0 && b == 0 && c == 0) || q.i < 0 || q.j < 0 || q.k < 0 ||
              q.i >= field.resolution || q.j >= field.resolution || q.k >= field.resolution)
            continue;
          const std::int32_t s = slot[linear(q)];
          if (s < 0) continue;
          // Plateaus: the lowest index of equal values is the minimum.
          const float e = field.distances[s];
          if (e < d || (e == d && static_cast<std::size_t>(s) < v)) isMinimum = false;
        }
    if (isMinimum) minima.push_back(v);
  }
  std::stable_sort(minima.begin(), minima.end(), [&](std::size_t x, std::size_t y) {
    return field.distances[x] < field.distances[y];
  });
  return minima;
}

std::vector<ExtractedPoint> autoCountPoints(const PredictedField& field,
                                            const ExtractionSettings& settings) {
  const std::vector<std::size_t> minima = localMinima(field);
  std::vector<ExtractedPoint> kept;
  for (std::size_t m : minima) {
    const ExtractedPoint candidate = pointAt(field, m, settings);
    if (!kept.empty() && candidate.distance > settings.maxDistance) break;  // sorted by distance
    bool suppressed = false;
    for (const auto& k : kept)
      if ((k.position - candidate.position).norm() < settings.nmsRadius) suppressed = true;
    if (!suppressed) kept.push_back(candidate);
  }
  return kept;
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
  float threshold = std::max(settings.maxDistance, 2.5f * voxel);
  ExtractionSettings relaxed = settings;
  relaxed.maxDistance = std::numeric_limits<float>::max();
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
  // Minima are computed once; only the filtering depends on the candidates.
  std::vector<std::vector<ExtractedPoint>> minima;
  for (const auto& f : fields) {
    ExtractionSettings all = base;
    all.maxDistance = std::numeric_limits<float>::max();
    all.nmsRadius = 0.0f;
    minima.push_back(autoCountPoints(f, all));
  }
  // Fields averaged over test-time symmetries are smoother than a model's fields on its own
  // training objects: their minima sit higher, hence the larger candidates.
  for (float maxDistance :
       {0.01f, 0.015f, 0.02f, 0.03f, 0.04f, 0.05f, 0.06f, 0.08f, 0.1f, 0.12f, 0.15f, 0.2f}) {
    for (float radius : {0.03f, 0.05f, 0.07f, 0.1f, 0.13f, 0.16f, 0.2f, 0.25f, 0.3f}) {
      double total = 0;
      for (std::size_t o = 0; o < fields.size(); ++o) {
        std::vector<Eigen::Vector3f> kept;
        for (const auto& m : minima[o]) {
          if (!kept.empty() && m.distance > maxDistance) break;
          bool suppressed = false;
          for (const auto& k : kept) suppressed |= (k - m.position).norm() < radius;
          if (!suppressed) kept.push_back(m.position);
        }
        total += cost(o, kept);
      }
      if (total < bestCost) {
        bestCost = total;
        best.maxDistance = maxDistance;
        best.nmsRadius = radius;
      }
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
