#include "core/features/voxel_aggregation.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/common/parallel_for.h"

namespace sagrid {

bool visibleInDepthMap(const DepthMapRef& map, const Eigen::Vector2f& uv, float depth,
                       float tolerance) {
  const float fx = uv.x() * map.width - 0.5f;
  const float fy = uv.y() * map.height - 0.5f;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  float farthest = -kBackgroundDepth;
  for (int dy = 0; dy <= 1; ++dy) {
    for (int dx = 0; dx <= 1; ++dx) {
      const int x = x0 + dx, y = y0 + dy;
      if (x < 0 || y < 0 || x >= map.width || y >= map.height) return true;
      farthest = std::max(farthest, map.depth[static_cast<std::size_t>(y) * map.width + x]);
    }
  }
  return depth <= farthest + tolerance;
}

VoxelAggregator::VoxelAggregator(std::vector<Eigen::Vector3f> points, int channels,
                                 Aggregation mode, float depthTolerance)
    : m_points(std::move(points)),
      m_channels(channels),
      m_mode(mode),
      m_tolerance(depthTolerance),
      m_sums(m_points.size() * channels, 0.0f),
      m_counts(m_points.size(), 0) {}

void VoxelAggregator::checkView(const FeatureMap& features, const DepthMapRef* depth) const {
  if (features.channels != m_channels) {
    throw Error("feature map has " + std::to_string(features.channels) + " channels, expected " +
                std::to_string(m_channels));
  }
  if (m_mode == Aggregation::OcclusionAware && (!depth || !depth->depth)) {
    throw Error("occlusion-aware aggregation needs the view's depth map");
  }
}

void VoxelAggregator::addSamples(const ViewCamera& camera, const FeatureMap& features,
                                 const DepthMapRef* depth, std::size_t begin, std::size_t end) {
  const bool occlusion = m_mode == Aggregation::OcclusionAware;
  // Project with the rotation inlined: this loop runs points x views times.
  const Eigen::Matrix3f rt = camera.rotation().transpose();
  const Eigen::Vector3f position = camera.position();
  const float f = 0.5f / std::tan(camera.fov / 2.0f);
  for (std::size_t p = begin; p < end; ++p) {
    const Eigen::Vector3f c = rt * (m_points[p] - position);
    if (c.z() <= 0.0f) {
      if (!occlusion) ++m_counts[p];  // TRELLIS: still a view, contributing nothing
      continue;
    }
    const Eigen::Vector2f uv(f * c.x() / c.z() + 0.5f, f * c.y() / c.z() + 0.5f);
    if (occlusion && !visibleInDepthMap(*depth, uv, c.z(), m_tolerance)) continue;
    addBilinearSample(features, uv, 1.0f, &m_sums[p * m_channels]);
    ++m_counts[p];
  }
}

void VoxelAggregator::addView(const ViewCamera& camera, const FeatureMap& features,
                              const DepthMapRef* depth) {
  checkView(features, depth);
  ++m_viewsAdded;
  addSamples(camera, features, depth, 0, m_points.size());
}

void VoxelAggregator::addViews(const std::vector<const ViewCamera*>& cameras,
                               const std::vector<const FeatureMap*>& features,
                               const std::vector<DepthMapRef>& depths, int threads) {
  if (features.size() != cameras.size() || (!depths.empty() && depths.size() != cameras.size()))
    throw Error("addViews: one feature map (and depth map) per camera expected");
  for (std::size_t v = 0; v < cameras.size(); ++v)
    checkView(*features[v], depths.empty() ? nullptr : &depths[v]);
  // Points are independent: how they are split between threads cannot change a sum.
  constexpr std::size_t kMinParallelPoints = 2048;
  parallelFor(
      m_points.size(), kMinParallelPoints, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t v = 0; v < cameras.size(); ++v)
          addSamples(*cameras[v], *features[v], depths.empty() ? nullptr : &depths[v], begin, end);
      });
  m_viewsAdded += static_cast<int>(cameras.size());
}

void VoxelAggregator::merge(const VoxelAggregator& other) {
  if (other.m_points.size() != m_points.size() || other.m_channels != m_channels) {
    throw Error("cannot merge aggregators over different points");
  }
  for (std::size_t i = 0; i < m_sums.size(); ++i) m_sums[i] += other.m_sums[i];
  for (std::size_t i = 0; i < m_counts.size(); ++i) m_counts[i] += other.m_counts[i];
  m_viewsAdded += other.m_viewsAdded;
}

std::vector<float> VoxelAggregator::mean() const {
  std::vector<float> out(m_sums.size(), 0.0f);
  for (std::size_t p = 0; p < m_counts.size(); ++p) {
    if (m_counts[p] == 0) continue;
    for (int ch = 0; ch < m_channels; ++ch) {
      out[p * m_channels + ch] = m_sums[p * m_channels + ch] / static_cast<float>(m_counts[p]);
    }
  }
  return out;
}

}  // namespace sagrid
