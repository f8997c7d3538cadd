#include "core/geometry/principal_axes.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace sagrid {

PrincipalAxes principalAxes(const std::vector<Eigen::Vector3f>& points) {
  PrincipalAxes out;
  if (points.empty()) return out;
  for (const auto& p : points) out.mean += p.cast<double>();
  out.mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points) {
    const Eigen::Vector3d d = p.cast<double>() - out.mean;
    covariance += d * d.transpose();
  }
  covariance /= static_cast<double>(points.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  for (int i = 0; i < 3; ++i) {
    out.axes.col(i) = solver.eigenvectors().col(2 - i);
    out.spread[i] = std::sqrt(std::max(0.0, solver.eigenvalues()[2 - i]));
  }
  return out;
}

}  // namespace sagrid
