// The principal axes of a point set: its mean, the eigenvectors of its covariance largest
// variance first, and the standard deviations along them. Shared by the shape summaries (convex
// parts' extents, control parts' axes).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sagrid {

struct PrincipalAxes {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns, largest spread first
  Eigen::Vector3d spread = Eigen::Vector3d::Zero();    // standard deviations along them
};

// Identity axes and zero spread for an empty set.
PrincipalAxes principalAxes(const std::vector<Eigen::Vector3f>& points);

}  // namespace sagrid
