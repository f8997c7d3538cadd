#include "core/grid/distance_transform.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace sagrid {
namespace {

std::size_t at(int n, int i, int j, int k) { return (static_cast<std::size_t>(i) * n + j) * n + k; }

TEST(DistanceTransform, MatchesBruteForceOnScatteredVoxels) {
  const int n = 12;
  std::vector<std::uint8_t> inside(n * n * n, 0);
  const int seeds[][3] = {{0, 0, 0}, {5, 7, 2}, {11, 3, 9}, {6, 6, 11}};
  for (const auto& s : seeds) inside[at(n, s[0], s[1], s[2])] = 1;
  const std::vector<float> distance = distanceToVoxels(inside, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        double best = 1e9;
        for (const auto& s : seeds)
          best = std::min(best, std::sqrt(double((i - s[0]) * (i - s[0]) + (j - s[1]) * (j - s[1]) +
                                                 (k - s[2]) * (k - s[2]))));
        ASSERT_NEAR(distance[at(n, i, j, k)], best, 1e-4) << i << " " << j << " " << k;
      }
}

TEST(DistanceTransform, EmptySetIsInfinitelyFar) {
  const std::vector<float> distance = distanceToVoxels(std::vector<std::uint8_t>(27, 0), 3);
  EXPECT_TRUE(std::isinf(distance[13]));
}

}  // namespace
}  // namespace sagrid
