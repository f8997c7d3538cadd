#include "core/grid/distance_transform.h"

#include <cmath>
#include <limits>

namespace sagrid {

namespace {

constexpr float kFar = 1e20f;

// Squared distance transform of one line (f: squared distances so far, stride apart in `values`).
void transformLine(float* values, std::size_t stride, int n, std::vector<float>& f,
                   std::vector<float>& d, std::vector<int>& v, std::vector<float>& z) {
  for (int q = 0; q < n; ++q) f[q] = values[q * stride];
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<float>::infinity();
  z[1] = std::numeric_limits<float>::infinity();
  for (int q = 1; q < n; ++q) {
    auto intersection = [&](int p) {
      return ((f[q] + float(q) * q) - (f[p] + float(p) * p)) / (2.0f * (q - p));
    };
    float s = intersection(v[k]);
    while (s <= z[k]) s = intersection(v[--k]);  // z[0] = -inf ends the loop
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = std::numeric_limits<float>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const float dq = float(q - v[k]);
    d[q] = dq * dq + f[v[k]];
  }
  for (int q = 0; q < n; ++q) values[q * stride] = d[q];
}

}  // namespace

std::vector<float> distanceToVoxels(const std::vector<std::uint8_t>& inside, int resolution) {
  const int n = resolution;
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  std::vector<float> squared(inside.size());
  bool any = false;
  for (std::size_t i = 0; i < inside.size(); ++i) {
    squared[i] = inside[i] ? 0.0f : kFar;
    any = any || inside[i];
  }
  if (!any) return std::vector<float>(inside.size(), std::numeric_limits<float>::infinity());
  std::vector<float> f(n), d(n), z(n + 1);
  std::vector<int> v(n);
  for (std::size_t i = 0; i < nn; ++i) transformLine(&squared[i * n], 1, n, f, d, v, z);  // z
  for (int a = 0; a < n; ++a)
    for (int c = 0; c < n; ++c) transformLine(&squared[a * nn + c], n, n, f, d, v, z);  // y
  for (std::size_t i = 0; i < nn; ++i) transformLine(&squared[i], nn, n, f, d, v, z);  // x
  for (float& s : squared) s = std::sqrt(s);
  return squared;
}

}  // namespace sagrid
