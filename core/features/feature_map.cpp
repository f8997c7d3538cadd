#include "core/features/feature_map.h"

#include <cmath>

namespace sagrid {

void addBilinearSample(const FeatureMap& map, const Eigen::Vector2f& uv, float weight, float* out) {
  const float fx = uv.x() * map.width - 0.5f;
  const float fy = uv.y() * map.height - 0.5f;
  const float x0f = std::floor(fx), y0f = std::floor(fy);
  const int x0 = static_cast<int>(x0f), y0 = static_cast<int>(y0f);
  const float ax = fx - x0f, ay = fy - y0f;
  const float w[4] = {(1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay};
  const int xs[4] = {x0, x0 + 1, x0, x0 + 1};
  const int ys[4] = {y0, y0, y0 + 1, y0 + 1};
  for (int t = 0; t < 4; ++t) {
    if (xs[t] < 0 || ys[t] < 0 || xs[t] >= map.width || ys[t] >= map.height || w[t] == 0.0f)
      continue;
    const float* texel = map.at(xs[t], ys[t]);
    const float tw = weight * w[t];
    for (int c = 0; c < map.channels; ++c) out[c] += tw * texel[c];
  }
}

}  // namespace sagrid
