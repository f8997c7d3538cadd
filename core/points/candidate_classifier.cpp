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
  return p;
}

std::vector<std::size_t> chooseCandidates(const std::vector<float>& p,
                                          const std::vector<PointCandidate>& candidates,
                                          const PointChoice& choice) {
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] > p[b]; });
  std::vector<std::size_t> taken;
  for (std::size_t i : order) {
    const float threshold = candidates[i].kept ? choice.keepThreshold : choice.addThreshold;
    if (p[i] < threshold) continue;
    // Two kept points stand as the passes spaced them.
    const bool suppressed = std::any_of(taken.begin(), taken.end(), [&](std::size_t t) {
      return !(candidates[t].kept && candidates[i].kept) &&
             (candidates[t].position - candidates[i].position).norm() < choice.nmsRadius;
    });
    if (!suppressed) taken.push_back(i);
  }
  if (taken.empty() && !order.empty()) taken.push_back(order.front());
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
