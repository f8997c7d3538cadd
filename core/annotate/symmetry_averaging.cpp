#include "core/annotate/symmetry_averaging.h"

#include <algorithm>
#include <numeric>

#include "core/common/error.h"
#include "core/model/affordance_model.h"

namespace sagrid {

const std::array<GridSymmetry, 8>& gridSymmetries() {
  static const std::array<GridSymmetry, 8> all = {
      GridSymmetry{0, false}, GridSymmetry{1, false}, GridSymmetry{2, false},
      GridSymmetry{3, false}, GridSymmetry{0, true},  GridSymmetry{1, true},
      GridSymmetry{2, true},  GridSymmetry{3, true}};
  return all;
}

VoxelIndex applySymmetry(const VoxelIndex& v, const GridSymmetry& s, int resolution) {
  // In voxel-centre coordinates about the grid centre a quarter turn is (x, y) -> (-y, x); in
  // indices that is (i, j) -> (R - 1 - j, i).
  VoxelIndex out = v;
  for (int t = 0; t < ((s.quarterTurns % 4) + 4) % 4; ++t) out = {resolution - 1 - out.j, out.i, out.k};
  if (s.flipX) out.i = resolution - 1 - out.i;
  return out;
}

namespace {

void transformVector(float* x, float* y, const GridSymmetry& s) {
  for (int t = 0; t < ((s.quarterTurns % 4) + 4) % 4; ++t) {
    const float nx = -*y, ny = *x;
    *x = nx, *y = ny;
  }
  if (s.flipX) *x = -*x;
}

std::int64_t linearIndex(const VoxelIndex& v, int r) {
  return (static_cast<std::int64_t>(v.i) * r + v.j) * r + v.k;
}

}  // namespace

FeatureGrid transformFeatureGrid(const FeatureGrid& grid, const GridSymmetry& s,
                                 const std::vector<std::array<int, 3>>& vectorChannels,
                                 std::vector<std::size_t>* order) {
  const std::size_t n = grid.voxels.size();
  if (grid.values.size() != n * static_cast<std::size_t>(grid.channels))
    throw InvalidArgument("feature grid: " + std::to_string(grid.values.size()) +
                          " values for " + std::to_string(n) + " voxels of " +
                          std::to_string(grid.channels) + " channels");
  std::vector<VoxelIndex> moved(n);
  for (std::size_t v = 0; v < n; ++v) moved[v] = applySymmetry(grid.voxels[v], s, grid.resolution);
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    return linearIndex(moved[a], grid.resolution) < linearIndex(moved[b], grid.resolution);
  });
  FeatureGrid out = grid;
  const auto c = static_cast<std::size_t>(grid.channels);
  for (std::size_t o = 0; o < n; ++o) {
    out.voxels[o] = moved[idx[o]];
    std::copy_n(grid.featuresOf(idx[o]), c, out.values.data() + o * c);
    float* f = out.values.data() + o * c;
    for (const auto& t : vectorChannels) transformVector(&f[t[0]], &f[t[1]], s);
  }
  if (order) *order = std::move(idx);
  return out;
}

std::vector<float> symmetryAveragedDistances(const model::AffordanceModel& model,
                                             const FeatureGrid& grid,
                                             const std::vector<std::array<int, 3>>& vectorChannels,
                                             int count) {
  count = std::clamp(count, 1, 8);
  // Every copy first, then their passes side by side (each on one thread: the same numbers
  // whatever the thread count), then the sum in the copies' order.
  std::vector<FeatureGrid> copies;
  std::vector<std::vector<std::size_t>> orders(static_cast<std::size_t>(count));
  copies.reserve(static_cast<std::size_t>(count));
  std::vector<const FeatureGrid*> passes{&grid};
  for (int i = 1; i < count; ++i) {
    copies.push_back(transformFeatureGrid(grid, gridSymmetries()[i], vectorChannels, &orders[i]));
    passes.push_back(&copies.back());
  }
  std::vector<std::vector<float>> fields = model.predictDistances(passes);
  std::vector<float> sum = std::move(fields[0]);
  for (int i = 1; i < count; ++i) {
    const std::vector<float>& d = fields[i];
    const std::vector<std::size_t>& order = orders[i];
    for (std::size_t o = 0; o < d.size(); ++o) sum[order[o]] += d[o];
  }
  for (float& d : sum) d /= static_cast<float>(count);
  return sum;
}

}  // namespace sagrid
