// Accuracy of predicted affordance points against ground truth, per object and aggregated per
// affordance type: the paper's metric (distance from the predicted point to the nearest
// ground-truth instance) and ours for multiple instances (Hungarian-matched mean error, precision
// and recall within a radius, share of objects with the right count). Distances in metres.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sagrid {

inline constexpr double kMatchRadiusMeters = 0.05;

struct ObjectMatch {
  std::size_t predicted = 0;
  std::size_t truth = 0;
  std::vector<double> matchedErrors;  // Hungarian-matched pairs (min(predicted, truth) of them)
  std::size_t truePositives = 0;      // matched pairs within the radius
};

// Points in one frame; errors scaled by metersPerUnit.
double nearestDistance(const Eigen::Vector3f& point, const std::vector<Eigen::Vector3f>& truth,
                       double metersPerUnit);
ObjectMatch matchPoints(const std::vector<Eigen::Vector3f>& predicted,
                        const std::vector<Eigen::Vector3f>& truth, double metersPerUnit,
                        double radiusMeters = kMatchRadiusMeters);

// Aggregates over the objects of one type.
struct TypeMetrics {
  std::size_t objects = 0;
  double paperError = 0;    // mean over objects of nearestDistance(single prediction)
  double matchedError = 0;  // mean over all matched pairs
  double precision = 0;     // true positives / predicted points
  double recall = 0;        // true positives / ground-truth points
  double countRight = 0;    // share of objects with predicted == truth count
};

class TypeMetricsAccumulator {
 public:
  void addSingle(double nearestError);  // the paper's single-point prediction of one object
  void addMatch(const ObjectMatch& m);  // the multi-instance prediction of one object
  TypeMetrics result() const;

 private:
  std::size_t m_singles = 0, m_matches = 0, m_predicted = 0, m_truth = 0, m_tp = 0, m_right = 0;
  double m_singleSum = 0;
  std::vector<double> m_errors;
};

}  // namespace sagrid
