#include "core/model/sparse_neighbors.h"

#include "core/common/error.h"

namespace sagrid::model {

NeighborTable buildNeighborTable(const std::vector<VoxelIndex>& voxels, int resolution, int kernel,
                                 int dilation, std::int64_t missingRow) {
  NeighborTable table;
  table.kernel = kernel;
  table.dilation = dilation;
  table.voxelCount = static_cast<std::int64_t>(voxels.size());
  table.missing = missingRow;
  const std::size_t n = static_cast<std::size_t>(resolution);
  // A dense index grid (4 bytes per voxel, 1 MiB at 64^3) makes each lookup O(1).
  std::vector<std::int32_t> slot(n * n * n, -1);
  auto linear = [&](int i, int j, int k) { return (static_cast<std::size_t>(i) * n + j) * n + k; };
  for (std::size_t v = 0; v < voxels.size(); ++v) {
    const auto& p = voxels[v];
    if (p.i < 0 || p.j < 0 || p.k < 0 || p.i >= resolution || p.j >= resolution ||
        p.k >= resolution)
      throw InvalidArgument("voxel outside the " + std::to_string(resolution) + "^3 grid");
    slot[linear(p.i, p.j, p.k)] = static_cast<std::int32_t>(v);
  }
  const int r = kernel / 2;
  const int taps = kernel * kernel * kernel;
  table.rows.resize(voxels.size() * taps);
  for (std::size_t v = 0; v < voxels.size(); ++v) {
    const auto& p = voxels[v];
    std::int64_t* out = table.rows.data() + v * taps;
    int t = 0;
    for (int a = -r; a <= r; ++a) {
      const int i = p.i + a * dilation;
      for (int b = -r; b <= r; ++b) {
        const int j = p.j + b * dilation;
        for (int c = -r; c <= r; ++c, ++t) {
          const int k = p.k + c * dilation;
          if (i < 0 || j < 0 || k < 0 || i >= resolution || j >= resolution || k >= resolution) {
            out[t] = missingRow;
            continue;
          }
          const std::int32_t s = slot[linear(i, j, k)];
          out[t] = s < 0 ? missingRow : static_cast<std::int64_t>(s);
        }
      }
    }
  }
  return table;
}

}  // namespace sagrid::model
