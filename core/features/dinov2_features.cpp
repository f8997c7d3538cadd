#include "core/features/dinov2_features.h"

#include <algorithm>

#include "core/common/thread_count.h"
#include "core/features/image_encoder.h"
#include "core/features/voxel_aggregation.h"
#include "core/render/multiview_renderer.h"
#include "core/render/trellis_views.h"

namespace sagrid {

namespace {
// Share of each cell of a g x g map covered by the object in a size x size mask.
std::vector<float> cellCoverage(const RenderedView& view, int gw, int gh) {
  std::vector<float> cover(static_cast<std::size_t>(gw) * gh, 0.0f);
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      if (!view.mask[static_cast<std::size_t>(y) * view.width + x]) continue;
      const int cx = x * gw / view.width, cy = y * gh / view.height;
      cover[static_cast<std::size_t>(cy) * gw + cx] += 1.0f;
    }
  }
  const float cellPixels = static_cast<float>(view.width) * view.height / (gw * gh);
  for (float& c : cover) c /= cellPixels;
  return cover;
}
}  // namespace

EncodedFeatures encodeViewsIntoVoxels(const Mesh& mesh, const SurfaceScene& scene,
                                      const VoxelGrid& grid, std::uint64_t seed, int views,
                                      ImageEncoder& encoder, Aggregation aggregation,
                                      bool aggregateVoxels) {
  const std::vector<ViewCamera> cameras = trellisViews(views, seed);
  const int channels = encoder.channels();
  std::vector<Eigen::Vector3f> points;
  if (aggregateVoxels) {
    for (const VoxelIndex& v : grid.occupiedVoxels())
      points.push_back(voxelCenter(v, grid.resolution()));
  }
  VoxelAggregator aggregator(points, channels, aggregation, voxelDepthTolerance(grid.resolution()));
  std::vector<double> descriptorSum(channels, 0.0);
  double descriptorWeight = 0.0;

  const MultiViewRenderer renderer(mesh, scene);
  const int batch = std::max(1, encoder.preferredBatch());
  std::vector<RenderedView> rendered(batch);
  std::vector<FeatureMap> maps;
  for (int first = 0; first < views; first += batch) {
    const int n = std::min(batch, views - first);
    const std::vector<ViewCamera> batchCameras(cameras.begin() + first,
                                               cameras.begin() + first + n);
    renderer.renderEach(batchCameras, encoder.renderSize(), defaultThreadCount(),
                        [&](int i, int, const RenderedView& view) { rendered[i] = view; });
    std::vector<const RenderedView*> viewPtrs;
    std::vector<const ViewCamera*> cameraPtrs;
    for (int i = 0; i < n; ++i) {
      viewPtrs.push_back(&rendered[i]);
      cameraPtrs.push_back(&batchCameras[i]);
    }
    encoder.encode(viewPtrs, cameraPtrs, maps);
    for (int i = 0; i < n; ++i) {
      const FeatureMap& map = maps[i];
      if (aggregateVoxels) {
        const DepthMapRef depth{rendered[i].width, rendered[i].height, rendered[i].depth.data()};
        aggregator.addView(batchCameras[i], map, &depth);
      }
      const std::vector<float> cover = cellCoverage(rendered[i], map.width, map.height);
      for (int cell = 0; cell < map.width * map.height; ++cell) {
        if (cover[cell] <= 0.0f) continue;
        const float* f = map.values.data() + static_cast<std::size_t>(cell) * channels;
        for (int c = 0; c < channels; ++c) descriptorSum[c] += cover[cell] * f[c];
        descriptorWeight += cover[cell];
      }
    }
  }
  EncodedFeatures out;
  if (aggregateVoxels) out.values = aggregator.mean();
  out.descriptor.resize(channels, 0.0f);
  if (descriptorWeight > 0) {
    for (int c = 0; c < channels; ++c)
      out.descriptor[c] = static_cast<float>(descriptorSum[c] / descriptorWeight);
  }
  return out;
}

}  // namespace sagrid
