// The distance colour map on the CPU, identical to shaders/colormap.glsl, for the legend.
#pragma once

#include <Eigen/Core>

namespace sagrid::ui {

Eigen::Vector3f viridis(float t);  // t in [0, 1]
// Near (0) = bright yellow, far (maxDistance) = dark purple.
inline Eigen::Vector3f distanceColor(float distance, float maxDistance) {
  return viridis(1.0f - distance / (maxDistance > 1e-12f ? maxDistance : 1e-12f));
}

}  // namespace sagrid::ui
