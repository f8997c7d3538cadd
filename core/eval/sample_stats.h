// Mean, sample standard deviation and range of a few numbers (folds, repeats) for the reports.
#pragma once

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace sagrid {

struct SampleStats {
  double mean = NAN, sd = NAN, lowest = NAN, highest = NAN;  // NaN for no values
};

// The sd divides by n - 1 (0 for one value).
inline SampleStats sampleStats(const std::vector<double>& values) {
  SampleStats s;
  if (values.empty()) return s;
  const auto n = static_cast<double>(values.size());
  s.mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  double squares = 0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sd = values.size() > 1 ? std::sqrt(squares / (n - 1)) : 0.0;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  s.lowest = *lo;
  s.highest = *hi;
  return s;
}

}  // namespace sagrid
