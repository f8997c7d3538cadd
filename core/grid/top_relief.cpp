#include "core/grid/top_relief.h"

#include <algorithm>

namespace sagrid {

namespace {

// A resolution x resolution map of ints over the columns (x, y).
struct ColumnMap {
  int n = 0;
  std::vector<int> values;
  ColumnMap(int size, int fill) : n(size), values(static_cast<std::size_t>(size) * size, fill) {}
  int& at(int x, int y) { return values[static_cast<std::size_t>(y) * n + x]; }
  int at(int x, int y) const { return values[static_cast<std::size_t>(y) * n + x]; }
};

// Median of every footprint column's 5x5 neighbourhood, over the footprint's columns in it (the
// upper one of the two middle values for an even count); columns outside keep -1.
ColumnMap footprintMedian5(const ColumnMap& height) {
  ColumnMap out(height.n, -1);
  std::array<int, 25> window{};
  for (int y = 0; y < height.n; ++y)
    for (int x = 0; x < height.n; ++x) {
      if (height.at(x, y) < 0) continue;
      int count = 0;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= height.n || qy >= height.n || height.at(qx, qy) < 0)
            continue;
          window[static_cast<std::size_t>(count++)] = height.at(qx, qy);
        }
      std::nth_element(window.begin(), window.begin() + count / 2, window.begin() + count);
      out.at(x, y) = window[static_cast<std::size_t>(count / 2)];
    }
  return out;
}

// Sizes of the 4-connected groups of set columns.
std::vector<int> groupSizes(const ColumnMap& set) {
  ColumnMap seen(set.n, 0);
  std::vector<int> sizes, stack;
  for (int start = 0; start < set.n * set.n; ++start) {
    if (!set.values[static_cast<std::size_t>(start)] ||
        seen.values[static_cast<std::size_t>(start)])
      continue;
    int size = 0;
    stack.assign(1, start);
    seen.values[static_cast<std::size_t>(start)] = 1;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      ++size;
      const int x = c % set.n, y = c / set.n;
      const int next[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      for (const auto& q : next) {
        if (q[0] < 0 || q[1] < 0 || q[0] >= set.n || q[1] >= set.n) continue;
        const std::size_t i = static_cast<std::size_t>(q[1]) * set.n + q[0];
        if (set.values[i] && !seen.values[i])
          seen.values[i] = 1, stack.push_back(static_cast<int>(i));
      }
    }
    sizes.push_back(size);
  }
  return sizes;
}

}  // namespace

std::array<float, kTopReliefSize> topRelief(const std::vector<VoxelIndex>& voxels, int resolution) {
  std::array<float, kTopReliefSize> out{};
  if (voxels.empty() || resolution <= 0) return out;
  const int n = resolution;
  ColumnMap height(n, -1);
  int zMin = n;
  for (const auto& v : voxels) {
    if (v.i < 0 || v.j < 0 || v.i >= n || v.j >= n) continue;
    height.at(v.i, v.j) = std::max(height.at(v.i, v.j), v.k);
    zMin = std::min(zMin, v.k);
  }
  const int top = *std::max_element(height.values.begin(), height.values.end());
  if (top < 0) return out;
  const int objectHeight = top - zMin + 1;
  auto inFootprint = [&](int x, int y) { return height.at(x, y) >= 0; };

  // Columns at least `depth` below the highest, with a higher column before and after them along
  // both the row and the column.
  const int depth = std::max(2, static_cast<int>(0.08 * objectHeight));
  auto high = [&](int x, int y) { return inFootprint(x, y) && height.at(x, y) > top - depth; };
  ColumnMap highBeforeX(n, 0), highAfterX(n, 0), highBeforeY(n, 0), highAfterY(n, 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      highBeforeX.at(x, y) = high(x, y) || (x > 0 && highBeforeX.at(x - 1, y));
      highBeforeY.at(x, y) = high(x, y) || (y > 0 && highBeforeY.at(x, y - 1));
    }
  for (int y = n - 1; y >= 0; --y)
    for (int x = n - 1; x >= 0; --x) {
      highAfterX.at(x, y) = high(x, y) || (x + 1 < n && highAfterX.at(x + 1, y));
      highAfterY.at(x, y) = high(x, y) || (y + 1 < n && highAfterY.at(x, y + 1));
    }

  const ColumnMap median = footprintMedian5(height);

  const double upperFrom = zMin + 0.6 * objectHeight;
  int footprint = 0, flat = 0, basin = 0, upper = 0, raised = 0, sunken = 0;
  double basinDepth = 0;
  ColumnMap raisedSet(n, 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      if (!inFootprint(x, y)) continue;
      const int h = height.at(x, y);
      ++footprint;
      flat += h >= top - 1;
      if (h <= top - depth && highBeforeX.at(x, y) && highAfterX.at(x, y) && highBeforeY.at(x, y) &&
          highAfterY.at(x, y)) {
        ++basin;
        basinDepth += top - h;
      }
      if (h < upperFrom) continue;
      ++upper;
      if (h >= median.at(x, y) + 1) ++raised, raisedSet.at(x, y) = 1;
      if (h <= median.at(x, y) - 1) ++sunken;
    }
  int spots = 0;
  for (int size : groupSizes(raisedSet)) spots += size >= 2 && size <= 0.05 * footprint;

  const float f = static_cast<float>(footprint);
  const float u = static_cast<float>(std::max(upper, 1));
  out[0] = static_cast<float>(flat) / f;
  out[1] = static_cast<float>(basin) / f;
  out[2] = basin ? static_cast<float>(basinDepth / basin / objectHeight) : 0.0f;
  out[3] = static_cast<float>(raised) / u;
  out[4] = static_cast<float>(sunken) / u;
  out[5] = static_cast<float>(spots);
  out[6] = static_cast<float>(upper) / f;
  return out;
}

}  // namespace sagrid
