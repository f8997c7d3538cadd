#include "core/eval/hungarian.h"

#include <cmath>
#include <limits>

#include "core/common/error.h"

namespace sagrid {

std::vector<int> hungarianAssignment(const std::vector<std::vector<double>>& input) {
  const std::size_t rows = input.size();
  if (rows == 0) return {};
  const std::size_t cols = input[0].size();
  for (const auto& r : input) {
    if (r.size() != cols) throw InvalidArgument("assignment: cost matrix rows differ in length");
    for (double v : r)
      if (!std::isfinite(v))
        throw InvalidArgument("assignment: cost matrix has a non-finite value");
  }
  if (cols == 0) return std::vector<int>(rows, -1);
  // The classic formulation needs n <= m; transpose when there are more rows than columns.
  const bool transposed = rows > cols;
  const std::size_t n = transposed ? cols : rows, m = transposed ? rows : cols;
  auto cost = [&](std::size_t i, std::size_t j) {
    return transposed ? input[j - 1][i - 1] : input[i - 1][j - 1];
  };
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0), v(m + 1, 0);
  std::vector<std::size_t> p(m + 1, 0), way(m + 1, 0);
  for (std::size_t i = 1; i <= n; ++i) {
    p[0] = i;
    std::size_t j0 = 0;
    std::vector<double> minv(m + 1, inf);
    std::vector<bool> used(m + 1, false);
    do {
      used[j0] = true;
      const std::size_t i0 = p[j0];
      double delta = inf;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = cost(i0, j) - u[i0] - v[j];
        if (cur < minv[j]) minv[j] = cur, way[j] = j0;
        if (minv[j] < delta) delta = minv[j], j1 = j;
      }
      for (std::size_t j = 0; j <= m; ++j) {
        if (used[j])
          u[p[j]] += delta, v[j] -= delta;
        else
          minv[j] -= delta;
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const std::size_t j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> result(rows, -1);
  for (std::size_t j = 1; j <= m; ++j) {
    if (p[j] == 0) continue;
    if (transposed)
      result[j - 1] = static_cast<int>(p[j] - 1);
    else
      result[p[j] - 1] = static_cast<int>(j - 1);
  }
  return result;
}

}  // namespace sagrid
