#include "core/mesh/up_axis_detection.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace sagrid {
namespace {

// Score differences below this are ties; the fallback axis wins a tie.
constexpr float kTieMargin = 0.05f;
// The last descriptor entries say which file axis the candidate is (the convention prior).
constexpr int kConventionEntries = 3;
// The lowest level is a band this fraction of the bounding-box diagonal thick (meshes from real
// files rarely have perfectly level bottoms).
constexpr float kLevelBand = 0.01f;
// Thinner than this fraction of the largest extent: a plate, whose up is its normal axis.
constexpr float kFlatRatio = 0.02f;
// Height-field grid over the cross-section, and surface samples that fill it.
constexpr int kGrid = 16;
constexpr int kSamples = 20000;
constexpr int kMaxSamplesPerTriangle = 64;

using Point2 = Eigen::Vector2f;

float cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Andrew's monotone chain; counter-clockwise, no repeated end point.
std::vector<Point2> convexHull(std::vector<Point2> points) {
  std::sort(points.begin(), points.end(), [](const Point2& a, const Point2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (points.size() < 3) return points;
  std::vector<Point2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

float polygonArea(const std::vector<Point2>& polygon) {
  float area = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5f * std::abs(area);
}

// Signed distance from p to the boundary of a counter-clockwise convex polygon: positive inside.
float insideDistance(const std::vector<Point2>& polygon, const Point2& p) {
  if (polygon.size() < 3) return -1e30f;
  float d = 1e30f;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    const Point2 edge = b - a;
    const float length = edge.norm();
    if (length <= 0) continue;
    d = std::min(d, cross(a, b, p) / length);
  }
  return d;
}

struct Surface {
  std::vector<float> area;
  std::vector<Eigen::Vector3f> normal, centroid;
  std::vector<Eigen::Vector3f> samples;  // spread over the surface by area, deterministic
  float totalArea = 0;
  Eigen::Vector3f centreOfMass = Eigen::Vector3f::Zero();  // of the surface, area-weighted
};

Surface measureSurface(const Mesh& mesh) {
  Surface s;
  std::vector<std::array<Eigen::Vector3f, 3>> corners;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3f& a = mesh.positions[t[0]];
    const Eigen::Vector3f n = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    const float doubleArea = n.norm();
    if (!(doubleArea > 0) || !std::isfinite(doubleArea)) continue;
    const Eigen::Vector3f c = (a + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0f;
    s.area.push_back(0.5f * doubleArea);
    s.normal.push_back(n / doubleArea);
    s.centroid.push_back(c);
    corners.push_back({a, mesh.positions[t[1]], mesh.positions[t[2]]});
    s.totalArea += 0.5f * doubleArea;
    s.centreOfMass += 0.5f * doubleArea * c;
  }
  if (!(s.totalArea > 0)) return s;
  s.centreOfMass /= s.totalArea;
  // Low-discrepancy (R2 sequence) points on each triangle, as many as its share of the area.
  for (std::size_t t = 0; t < corners.size(); ++t) {
    const int k = std::clamp(static_cast<int>(std::lround(s.area[t] / s.totalArea * kSamples)), 1,
                             kMaxSamplesPerTriangle);
    for (int j = 0; j < k; ++j) {
      float r1 = std::fmod(0.5f + 0.7548777f * static_cast<float>(j), 1.0f);
      float r2 = std::fmod(0.5f + 0.5698403f * static_cast<float>(j), 1.0f);
      if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
      const auto& c = corners[t];
      s.samples.push_back(c[0] + r1 * (c[1] - c[0]) + r2 * (c[2] - c[0]));
    }
  }
  return s;
}

struct CandidateFrame {
  Eigen::Vector3f e;
  int a = 0, b = 0;  // the horizontal axes
  float lowest = 0, height = 0, crossSection = 0, band = 0;
  Eigen::Vector3f boxMin;
  Eigen::Vector3f size;
};

CandidateFrame frameFor(const Mesh& mesh, UpAxis up, const Eigen::AlignedBox3f& box) {
  CandidateFrame f;
  f.e = upAxisVector(up);
  int vertical = 0;
  f.e.cwiseAbs().maxCoeff(&vertical);
  f.a = (vertical + 1) % 3;
  f.b = (vertical + 2) % 3;
  f.size = box.sizes();
  f.boxMin = box.min();
  f.crossSection = std::max(f.size[f.a] * f.size[f.b], 1e-12f);
  f.height = f.size[vertical];
  f.band = kLevelBand * f.size.norm();
  f.lowest = 1e30f;
  for (const auto& p : mesh.positions) f.lowest = std::min(f.lowest, f.e.dot(p));
  return f;
}

float supportAt(const Mesh& mesh, const CandidateFrame& f, float level, float sign,
                std::vector<Point2>* hullOut = nullptr) {
  std::vector<Point2> points;
  for (const auto& p : mesh.positions) {
    if (sign * (f.e.dot(p) - level) <= f.band) points.emplace_back(p[f.a], p[f.b]);
  }
  std::vector<Point2> hull = convexHull(std::move(points));
  const float fraction = std::min(1.0f, polygonArea(hull) / f.crossSection);
  if (hullOut) *hullOut = std::move(hull);
  return fraction;
}

// Fills the descriptor of candidate `up` and its interpretable evidence.
UpAxisDescriptor describe(const Mesh& mesh, const Surface& surface, UpAxis up,
                          const Eigen::AlignedBox3f& box, UpAxisEvidence& ev) {
  const CandidateFrame f = frameFor(mesh, up, box);
  const float highest = f.lowest + f.height;
  UpAxisDescriptor d{};
  auto normHeight = [&](const Eigen::Vector3f& p) {
    return f.height > 0 ? std::clamp((f.e.dot(p) - f.lowest) / f.height, 0.0f, 1.0f) : 0.5f;
  };

  std::vector<Point2> support;
  ev.supportArea = supportAt(mesh, f, f.lowest, 1.0f, &support);
  ev.topSupport = supportAt(mesh, f, highest, -1.0f);
  float flatBottom = 0, flatTop = 0, weightedHeight = 0, horizontal = 0;
  for (std::size_t t = 0; t < surface.area.size(); ++t) {
    const float w = surface.area[t] / surface.totalArea;
    const float h = normHeight(surface.centroid[t]);
    d[std::min(7, static_cast<int>(h * 8))] += w;
    const float c = surface.normal[t].dot(f.e);
    d[8 + (c > 0.9f ? 0 : c > 0.5f ? 1 : c >= -0.5f ? 2 : c >= -0.9f ? 3 : 4)] += w;
    weightedHeight += w * h;
    if (std::abs(c) > 0.9f) {
      horizontal += w;
      const float above = f.e.dot(surface.centroid[t]) - f.lowest;
      if (above <= f.band) flatBottom += surface.area[t];
      if (f.height - above <= f.band) flatTop += surface.area[t];
    }
  }
  ev.flatBottom = std::min(1.0f, flatBottom / f.crossSection);
  ev.massHeight = weightedHeight;
  const Point2 com(surface.centreOfMass[f.a], surface.centreOfMass[f.b]);
  const float comHeight = std::max(f.e.dot(surface.centreOfMass) - f.lowest, 1e-12f);
  const float inside = insideDistance(support, com);
  ev.tipping = support.size() < 3 ? -1.0f
                                  : std::atan2(std::max(inside, -comHeight), comHeight) /
                                        static_cast<float>(M_PI / 2);
  d[13] = ev.supportArea;
  d[14] = ev.topSupport;
  d[15] = ev.flatBottom;
  d[16] = std::min(1.0f, flatTop / f.crossSection);
  d[17] = ev.tipping;
  d[18] = ev.massHeight - 0.5f;
  const float widest = std::max({f.size[f.a], f.size[f.b], 1e-12f});
  d[19] = std::clamp(std::log(std::max(f.height, 1e-12f) / widest), -3.0f, 3.0f);

  // Height fields seen from above and from below: how deep the top surface lies under the
  // highest point (cooktops under a backguard, basins under a faucet) and how plain the bottom is.
  std::vector<float> top(kGrid * kGrid, -1.0f), bottom(kGrid * kGrid, 2.0f);
  for (const auto& p : surface.samples) {
    const auto cell = [&](int axis) {
      const float u = f.size[axis] > 0 ? (p[axis] - f.boxMin[axis]) / f.size[axis] : 0.5f;
      return std::clamp(static_cast<int>(u * kGrid), 0, kGrid - 1);
    };
    const int i = cell(f.a) * kGrid + cell(f.b);
    const float h = normHeight(p);
    top[i] = std::max(top[i], h);
    bottom[i] = std::min(bottom[i], h);
  }
  float n = 0, topSum = 0, topSq = 0, botSum = 0, botSq = 0;
  for (int i = 0; i < kGrid * kGrid; ++i) {
    if (top[i] < 0) continue;
    ++n;
    topSum += 1 - top[i];
    topSq += (1 - top[i]) * (1 - top[i]);
    botSum += bottom[i];
    botSq += bottom[i] * bottom[i];
  }
  if (n > 0) {
    d[20] = topSum / n;
    d[21] = std::sqrt(std::max(0.0f, topSq / n - d[20] * d[20]));
    d[22] = botSum / n;
    d[23] = std::sqrt(std::max(0.0f, botSq / n - d[22] * d[22]));
  }
  d[24] = horizontal;
  // Which axis the candidate is: lets the fit learn the file conventions' prior.
  const Eigen::Vector3f e = f.e;
  d[25] = std::abs(e.y());
  d[26] = std::abs(e.z());
  d[27] = e.sum() < 0 ? 1.0f : 0.0f;
  return d;
}

// Where each part of the flat parameter array starts.
constexpr int kHiddenAt = kUpAxisDescriptorSize;
constexpr int kBiasAt = kHiddenAt + kUpAxisHidden * kUpAxisDescriptorSize;
constexpr int kOutAt = kBiasAt + kUpAxisHidden;
static_assert(kOutAt + kUpAxisHidden == kUpAxisParameterCount, "parameter layout");

float inner(const float* w, const UpAxisDescriptor& d) {
  return std::inner_product(d.begin(), d.end(), w, 0.0f);
}

// The hidden units' activations tanh(hidden[h] . d + bias[h]).
std::array<float, kUpAxisHidden> hiddenActivations(const UpAxisWeights& w,
                                                   const UpAxisDescriptor& d) {
  std::array<float, kUpAxisHidden> t{};
  for (int h = 0; h < kUpAxisHidden; ++h) {
    t[h] = std::tanh(w[kBiasAt + h] + inner(&w[kHiddenAt + h * kUpAxisDescriptorSize], d));
  }
  return t;
}

// Softmax over six scores.
std::array<float, 6> probabilities(const std::array<float, 6>& scores) {
  const float top = *std::max_element(scores.begin(), scores.end());
  std::array<float, 6> p{};
  float sum = 0;
  for (std::size_t i = 0; i < 6; ++i) sum += p[i] = std::exp(scores[i] - top);
  for (auto& v : p) v /= sum;
  return p;
}

}  // namespace

const UpAxisWeights& defaultUpAxisWeights() {
  // The linear term fitted (before the hidden layer existed) on generated stoves and sinks turned
  // six ways and Sweet Home 3D distractors; the hidden layer is zero. Refits with the hidden layer
  // (`sagrid up-axis --fit`, see README) rank generated objects far better (72.5 % -> 94-98 % on
  // the bench val split turned six ways) but Sweet Home 3D objects held out of the fit no better
  // (real-val + distractor val split as shipped, y up: 13/16 -> 10-11/16): not built in.
  static const UpAxisWeights weights = {
      0.7134f, -1.5322f, 0.0063f, 1.0145f, 0.1060f, 0.7818f, 0.9322f, -2.0222f, 2.7906f, -1.9866f, -0.6456f, -2.6157f, 2.4571f, 4.5278f, 0.7728f, -1.7277f, 0.5084f, 0.6851f, 1.2761f, 1.9389f, 2.6724f, -3.5331f, -1.6896f, 2.0137f, 5.2476f, 0.9900f, 0.8250f, -1.2432f};
  return weights;
}

float upAxisScore(const UpAxisWeights& w, const UpAxisDescriptor& d) {
  const auto t = hiddenActivations(w, d);
  float score = inner(&w[0], d);
  for (int h = 0; h < kUpAxisHidden; ++h) score += w[kOutAt + h] * t[h];
  return score;
}

std::vector<UpAxisDescriptor> upAxisDescriptors(const Mesh& mesh) {
  const Surface surface = measureSurface(mesh);
  Eigen::AlignedBox3f box;
  for (const auto& p : mesh.positions) box.extend(p);
  if (!(surface.totalArea > 0) || !std::isfinite(surface.totalArea) || box.isEmpty() ||
      !(box.sizes().norm() > 0)) {
    return {};
  }
  std::vector<UpAxisDescriptor> out;
  UpAxisEvidence unused;
  for (UpAxis up : kAllUpAxes) out.push_back(describe(mesh, surface, up, box, unused));
  return out;
}

UpAxisDetection detectUpAxis(const Mesh& mesh, UpAxis fallback, const UpAxisWeights& weights) {
  UpAxisDetection result;
  result.axis = fallback;
  const Surface surface = measureSurface(mesh);
  Eigen::AlignedBox3f box;
  for (const auto& p : mesh.positions) box.extend(p);
  if (!(surface.totalArea > 0) || !std::isfinite(surface.totalArea) || box.isEmpty() ||
      !(box.sizes().norm() > 0)) {
    result.degenerate = true;
    return result;
  }
  // The geometric part of each score (without the file-convention prior of the last three
  // descriptor entries): when the shape itself does not prefer the winner over the fallback
  // (a sphere, a cube), the fallback stands.
  std::array<float, 6> geometric{};
  for (std::size_t i = 0; i < 6; ++i) {
    const UpAxisDescriptor d = describe(mesh, surface, kAllUpAxes[i], box, result.evidence[i]);
    result.scores[i] = upAxisScore(weights, d);
    UpAxisDescriptor shapeOnly = d;
    std::fill(shapeOnly.end() - kConventionEntries, shapeOnly.end(), 0.0f);
    geometric[i] = upAxisScore(weights, shapeOnly);
  }
  const std::array<float, 6> p = probabilities(result.scores);
  result.probabilities = p;
  const std::size_t fallbackIndex = static_cast<std::size_t>(fallback);
  std::size_t best = fallbackIndex;
  for (std::size_t i = 0; i < 6; ++i) {
    if (result.scores[i] > result.scores[best]) best = i;
  }
  if (std::abs(geometric[best] - geometric[fallbackIndex]) < kTieMargin) best = fallbackIndex;

  // A plate (or a single triangle) has its normal axis up, but which face is up cannot be told
  // from the shape: take the positive side (or the fallback's) with a low confidence.
  int thin = 0;
  const Eigen::Vector3f size = box.sizes();
  if (size.minCoeff(&thin) <= kFlatRatio * size.maxCoeff()) {
    result.flat = true;
    const UpAxis positive = kAllUpAxes[2 * thin], negative = kAllUpAxes[2 * thin + 1];
    result.axis = fallback == negative ? negative : positive;
    result.confidence = std::min(0.1f, std::abs(p[2 * thin] - p[2 * thin + 1]));
    return result;
  }
  float runnerUp = 0;
  for (std::size_t i = 0; i < 6; ++i) {
    if (i != best) runnerUp = std::max(runnerUp, p[i]);
  }
  result.axis = kAllUpAxes[best];
  result.confidence = std::clamp(p[best] - runnerUp, 0.0f, 1.0f);
  return result;
}

namespace {

// The fit's fixed starting point: no linear term, small deterministic hidden weights (a
// low-discrepancy sequence in [-0.3, 0.3]) and output weights (in [-0.1, 0.1]).
UpAxisWeights initialUpAxisWeights() {
  UpAxisWeights w{};
  for (int k = kHiddenAt; k < kBiasAt; ++k) {
    w[k] = 0.6f * (std::fmod(0.5f + 0.6180340f * static_cast<float>(k), 1.0f) - 0.5f);
  }
  for (int h = 0; h < kUpAxisHidden; ++h) {
    w[kOutAt + h] = 0.2f * (std::fmod(0.5f + 0.7548777f * static_cast<float>(h), 1.0f) - 0.5f);
  }
  return w;
}

// Adds g * d score(d) / d weights to `grad`.
void addScoreGradient(const UpAxisWeights& w, const UpAxisDescriptor& d, float g,
                      UpAxisWeights& grad) {
  const auto t = hiddenActivations(w, d);
  for (int k = 0; k < kUpAxisDescriptorSize; ++k) grad[k] += g * d[k];
  for (int h = 0; h < kUpAxisHidden; ++h) {
    grad[kOutAt + h] += g * t[h];
    const float back = g * w[kOutAt + h] * (1 - t[h] * t[h]);
    grad[kBiasAt + h] += back;
    float* row = &grad[kHiddenAt + h * kUpAxisDescriptorSize];
    for (int k = 0; k < kUpAxisDescriptorSize; ++k) row[k] += back * d[k];
  }
}

int bestCandidate(const UpAxisWeights& w, const UpAxisExample& e) {
  int best = 0;
  float bestScore = upAxisScore(w, e.candidates[0]);
  for (int i = 1; i < 6; ++i) {
    const float s = upAxisScore(w, e.candidates[i]);
    if (s > bestScore) best = i, bestScore = s;
  }
  return best;
}

}  // namespace

UpAxisWeights fitUpAxisWeights(const std::vector<UpAxisExample>& examples, int iterations, float l2,
                               float* accuracy) {
  UpAxisWeights w = initialUpAxisWeights();
  std::vector<const UpAxisExample*> usable;
  for (const auto& e : examples) {
    if (e.candidates.size() == 6 && e.up >= 0 && e.up < 6) usable.push_back(&e);
  }
  if (usable.empty()) return defaultUpAxisWeights();
  // Adam on the mean negative log-likelihood of the true axis among the six.
  float totalWeight = 0;
  for (const auto* e : usable) totalWeight += e->weight;
  UpAxisWeights m{}, v{};
  const float rate = 0.01f, beta1 = 0.9f, beta2 = 0.999f;
  for (int it = 1; it <= iterations; ++it) {
    UpAxisWeights grad{};
    for (const auto* e : usable) {
      std::array<float, 6> s{};
      for (int i = 0; i < 6; ++i) s[i] = upAxisScore(w, e->candidates[i]);
      const auto p = probabilities(s);
      for (int i = 0; i < 6; ++i) {
        addScoreGradient(w, e->candidates[i], e->weight * (p[i] - (i == e->up ? 1.0f : 0.0f)),
                         grad);
      }
    }
    for (int k = 0; k < kUpAxisParameterCount; ++k) {
      const float g = grad[k] / totalWeight + l2 * w[k];
      m[k] = beta1 * m[k] + (1 - beta1) * g;
      v[k] = beta2 * v[k] + (1 - beta2) * g * g;
      const float mh = m[k] / (1 - std::pow(beta1, static_cast<float>(it)));
      const float vh = v[k] / (1 - std::pow(beta2, static_cast<float>(it)));
      w[k] -= rate * mh / (std::sqrt(vh) + 1e-8f);
    }
  }
  if (accuracy) {
    int right = 0;
    for (const auto* e : usable) right += bestCandidate(w, *e) == e->up;
    *accuracy = static_cast<float>(right) / static_cast<float>(usable.size());
  }
  return w;
}

}  // namespace sagrid
