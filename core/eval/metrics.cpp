#include "core/eval/metrics.h"

#include <limits>
#include <numeric>

#include "core/eval/hungarian.h"

namespace sagrid {

double nearestDistance(const Eigen::Vector3f& point, const std::vector<Eigen::Vector3f>& truth,
                       double metersPerUnit) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : truth) best = std::min(best, static_cast<double>((point - t).norm()));
  return best * metersPerUnit;
}

ObjectMatch matchPoints(const std::vector<Eigen::Vector3f>& predicted,
                        const std::vector<Eigen::Vector3f>& truth, double metersPerUnit,
                        double radiusMeters) {
  ObjectMatch m;
  m.predicted = predicted.size();
  m.truth = truth.size();
  if (predicted.empty() || truth.empty()) return m;
  std::vector<std::vector<double>> cost(predicted.size(), std::vector<double>(truth.size()));
  for (std::size_t i = 0; i < predicted.size(); ++i)
    for (std::size_t j = 0; j < truth.size(); ++j)
      cost[i][j] = (predicted[i] - truth[j]).norm() * metersPerUnit;
  const auto assignment = hungarianAssignment(cost);
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    if (assignment[i] < 0) continue;
    const double e = cost[i][assignment[i]];
    m.matchedErrors.push_back(e);
    if (e <= radiusMeters) ++m.truePositives;
  }
  return m;
}

void TypeMetricsAccumulator::addSingle(double nearestError) {
  ++m_singles;
  m_singleSum += nearestError;
}

void TypeMetricsAccumulator::addMatch(const ObjectMatch& m) {
  ++m_matches;
  m_predicted += m.predicted;
  m_truth += m.truth;
  m_tp += m.truePositives;
  m_right += m.predicted == m.truth;
  m_errors.insert(m_errors.end(), m.matchedErrors.begin(), m.matchedErrors.end());
}

TypeMetrics TypeMetricsAccumulator::result() const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  TypeMetrics r;
  r.objects = std::max(m_singles, m_matches);
  r.paperError = m_singles ? m_singleSum / m_singles : nan;
  r.matchedError = m_errors.empty()
                       ? nan
                       : std::accumulate(m_errors.begin(), m_errors.end(), 0.0) / m_errors.size();
  r.precision = m_predicted ? static_cast<double>(m_tp) / m_predicted : nan;
  r.recall = m_truth ? static_cast<double>(m_tp) / m_truth : nan;
  r.countRight = m_matches ? static_cast<double>(m_right) / m_matches : nan;
  return r;
}

}  // namespace sagrid
