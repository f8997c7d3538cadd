#include "core/points/candidate_classifier.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Dense>

#include "core/common/error.h"

namespace sagrid {

namespace {
double sigmoid(double z) { return 1.0 / (1.0 + std::exp(-std::clamp(z, -40.0, 40.0))); }
}  // namespace

float CandidateClassifier::probability(const std::vector<float>& features) const {
  if (trees) return static_cast<float>(sigmoid(trees->score(features)));
  if (features.size() != weights.size())
    throw InvalidArgument("candidate classifier: " + std::to_string(features.size()) +
                          " features, the classifier reads " + std::to_string(weights.size()));
  double z = bias;
  for (std::size_t i = 0; i < features.size(); ++i)
    z += weights[i] * (features[i] - mean[i]) / scale[i];
  return static_cast<float>(sigmoid(z));
}

std::vector<float> candidateProbabilities(const CandidateClassifier& classifier,
                                          const std::vector<PointCandidate>& candidates) {
  std::vector<float> p;
  for (const auto& c : candidates) p.push_back(classifier.probability(c.features));
  return classifier.contextTrees ? bothLooks(*classifier.contextTrees, candidates, p) : p;
}

std::vector<float> bothLooks(const BoostedTrees& contextTrees,
                             const std::vector<PointCandidate>& candidates,
                             const std::vector<float>& firstLook) {
  const auto rows = withContext(candidates, firstLook);  // checks the sizes
  // Both looks decide together (their geometric mean): the second alone chose better sets of
  // points but a worse first point (resources/models/README.md).
  std::vector<float> p(rows.size());
  for (std::size_t c = 0; c < rows.size(); ++c)
    p[c] = std::sqrt(firstLook[c] * static_cast<float>(sigmoid(contextTrees.score(rows[c]))));
  return p;
}

const std::vector<std::string>& contextFeatureNames() {
  static const std::vector<std::string> names = {
      "first_look", "against_best", "rank", "height_from_best", "shape_from_best", "like_others"};
  return names;
}

namespace {
// How a candidate's part and place differ from another's: height, facing and part shape (size,
// flatness, roundness, on a part at all, separated by material), each a share.
struct Difference {
  float height = 0, shape = 0;
};
Difference differenceOf(const std::vector<float>& a, const std::vector<float>& b) {
  static const std::size_t height = candidateFeatureIndex("height"),
                           facing = candidateFeatureIndex("facing_up");
  static const std::vector<std::size_t> shape = {
      candidateFeatureIndex("on_part"), candidateFeatureIndex("part_size"),
      candidateFeatureIndex("part_flatness"), candidateFeatureIndex("part_roundness"),
      candidateFeatureIndex("part_by_material")};
  Difference d;
  d.height = std::abs(a[height] - b[height]) + std::abs(a[facing] - b[facing]) / 2;
  for (std::size_t f : shape) d.shape += std::abs(a[f] - b[f]);
  return d;
}
// The other candidates a candidate is compared with: the most probable few.
constexpr std::size_t kCompany = 4;
// Differences at which a look-alike counts 1/e as much (height and facing, part shape).
constexpr float kAlikeHeight = 0.1f, kAlikeShape = 0.2f;
}  // namespace

std::vector<std::vector<float>> contextFeatures(const std::vector<PointCandidate>& candidates,
                                                const std::vector<float>& p) {
  const std::size_t n = candidates.size();
  if (p.size() != n)
    throw InvalidArgument("candidate context: " + std::to_string(p.size()) + " probabilities for " +
                          std::to_string(n) + " candidates");
  std::vector<std::vector<float>> out(n, std::vector<float>(kContextFeatureCount, 0.0f));
  if (n == 0) return out;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return p[a] > p[b]; });
  std::vector<float> rank(n);
  for (std::size_t r = 0; r < n; ++r)
    rank[order[r]] = n > 1 ? static_cast<float>(r) / static_cast<float>(n - 1) : 0.0f;
  const std::size_t best = order.front();
  for (std::size_t c = 0; c < n; ++c) {
    const auto& f = candidates[c].features;
    std::vector<float>& x = out[c];
    x[0] = p[c];
    x[1] = p[c] / std::max(p[best], 1e-6f);
    x[2] = rank[c];
    const Difference fromBest = differenceOf(f, candidates[best].features);
    x[3] = fromBest.height;
    x[4] = fromBest.shape;
    float alike = 0;
    for (std::size_t r = 0; r < std::min(kCompany, n); ++r) {
      const std::size_t o = order[r];
      if (o == c) continue;
      const Difference d = differenceOf(f, candidates[o].features);
      alike = std::max(alike, p[o] * std::exp(-d.height / kAlikeHeight - d.shape / kAlikeShape));
    }
    x[5] = alike;
  }
  return out;
}

std::vector<std::vector<float>> withContext(const std::vector<PointCandidate>& candidates,
                                            const std::vector<float>& p) {
  auto rows = contextFeatures(candidates, p);
  for (std::size_t c = 0; c < rows.size(); ++c)
    rows[c].insert(rows[c].begin(), candidates[c].features.begin(), candidates[c].features.end());
  return rows;
}

std::vector<std::size_t> chooseCandidates(const std::vector<float>& p,
                                          const std::vector<PointCandidate>& candidates,
                                          const PointChoice& choice) {
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return p[a] > p[b]; });
  std::vector<std::size_t> taken;
  std::vector<char> isTaken(candidates.size(), 0);
  // Two kept points stand as the passes spaced them.
  const auto suppressed = [&](std::size_t i) {
    return std::any_of(taken.begin(), taken.end(), [&](std::size_t t) {
      return !(candidates[t].kept && candidates[i].kept) &&
             (candidates[t].position - candidates[i].position).norm() < choice.nmsRadius;
    });
  };
  // A taken candidate brings its places on its part's copies at or above the copy threshold.
  const auto take = [&](std::size_t i) {
    taken.push_back(i);
    isTaken[i] = 1;
    for (std::size_t j : candidates[i].copies)
      if (j < candidates.size() && !isTaken[j] && p[j] >= choice.copyThreshold && !suppressed(j)) {
        taken.push_back(j);
        isTaken[j] = 1;
      }
  };
  for (std::size_t i : order) {
    const float threshold = candidates[i].kept ? choice.keepThreshold : choice.addThreshold;
    if (p[i] < threshold || isTaken[i]) continue;
    if (!suppressed(i)) take(i);
  }
  if (taken.empty() && !order.empty()) take(order.front());
  return taken;
}

CandidateClassifier fitCandidateClassifier(const std::vector<std::vector<float>>& rows,
                                           const std::vector<bool>& positive,
                                           const std::vector<float>& weight, double ridge) {
  if (rows.empty()) throw InvalidArgument("candidate classifier: no candidates to fit");
  if (positive.size() != rows.size() || weight.size() != rows.size())
    throw InvalidArgument("candidate classifier: labels or weights do not match the candidates");
  const std::size_t n = rows.size(), d = rows.front().size();
  double wPos = 0, wNeg = 0;
  for (std::size_t r = 0; r < n; ++r) {
    if (rows[r].size() != d)
      throw InvalidArgument("candidate classifier: candidates with different feature counts");
    (positive[r] ? wPos : wNeg) += weight[r];
  }
  if (wPos <= 0 || wNeg <= 0)
    throw InvalidArgument("candidate classifier: the candidates need points and non-points");

  CandidateClassifier c;
  c.mean.assign(d, 0);
  c.scale.assign(d, 1);
  const double wSum = wPos + wNeg;
  for (std::size_t j = 0; j < d; ++j) {
    double m = 0, v = 0;
    for (std::size_t r = 0; r < n; ++r) m += weight[r] * rows[r][j];
    m /= wSum;
    for (std::size_t r = 0; r < n; ++r) v += weight[r] * (rows[r][j] - m) * (rows[r][j] - m);
    c.mean[j] = static_cast<float>(m);
    c.scale[j] = static_cast<float>(std::max(std::sqrt(v / wSum), 1e-6));
  }
  Eigen::MatrixXd x(n, d + 1);
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t j = 0; j < d; ++j) x(r, j) = (rows[r][j] - c.mean[j]) / c.scale[j];
    x(r, d) = 1.0;
  }
  // Weights normalized to sum n, so the ridge means the same whatever the weights' scale.
  Eigen::VectorXd w(n), y(n), beta = Eigen::VectorXd::Zero(d + 1);
  for (std::size_t r = 0; r < n; ++r) {
    w(r) = weight[r] * static_cast<double>(n) / wSum;
    y(r) = positive[r] ? 1.0 : 0.0;
  }
  Eigen::MatrixXd penalty = ridge * Eigen::MatrixXd::Identity(d + 1, d + 1);
  penalty(d, d) = 0;  // the bias is not shrunk
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Eigen::VectorXd z = x * beta;
    Eigen::VectorXd p(n), h(n);
    for (std::size_t r = 0; r < n; ++r) {
      p(r) = sigmoid(z(r));
      h(r) = w(r) * std::max(p(r) * (1 - p(r)), 1e-9);
    }
    const Eigen::VectorXd gradient = x.transpose() * (w.cwiseProduct(p - y)) + penalty * beta;
    const Eigen::MatrixXd hessian = x.transpose() * h.asDiagonal() * x + penalty;
    const Eigen::VectorXd step = hessian.ldlt().solve(gradient);
    beta -= step;
    if (step.norm() < 1e-8) break;
  }
  c.weights.resize(d);
  for (std::size_t j = 0; j < d; ++j) c.weights[j] = static_cast<float>(beta(j));
  c.bias = static_cast<float>(beta(d));
  return c;
}

}  // namespace sagrid
