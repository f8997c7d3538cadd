// Aggregation of per-view 2D features into 3D points (voxel centres), as TRELLIS does it:
// project each point into each view, sample the feature map bilinearly, average over views.
// The occlusion-aware variant counts a view only when the view's depth map shows the point
// (depth test with a tolerance of about one voxel), so hidden surfaces do not receive the colour
// of whatever covers them.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/features/feature_map.h"
#include "core/features/feature_pipeline.h"
#include "core/render/rendered_view.h"
#include "core/render/view_camera.h"

namespace sagrid {

// A z-depth map of a view (rendered_view.h conventions): kBackgroundDepth where nothing was hit.
struct DepthMapRef {
  int width = 0;
  int height = 0;
  const float* depth = nullptr;
};

// True when `depth` (the point's z-depth) is not behind the surface the depth map shows at uv by
// more than `tolerance`. Uses the farthest of the 2x2 texels around uv, so points on silhouettes
// and thin parts are not rejected by one neighbouring foreground texel; outside the map = visible.
bool visibleInDepthMap(const DepthMapRef& map, const Eigen::Vector2f& uv, float depth,
                       float tolerance);

class VoxelAggregator {
 public:
  // `points` in the world frame of the cameras (normalized object frame).
  VoxelAggregator(std::vector<Eigen::Vector3f> points, int channels, Aggregation mode,
                  float depthTolerance);

  // Adds one view. `depth` is required for Aggregation::OcclusionAware (ignored for Mean).
  void addView(const ViewCamera& camera, const FeatureMap& features, const DepthMapRef* depth);
  // Adds several views on `threads` workers (<= 0: defaultThreadCount), the points split between
  // them: each point still adds the views in the order given, so the sums are bit for bit those
  // of addView one view after the other, whatever the thread count. `depths` as for addView
  // (empty for Mean).
  void addViews(const std::vector<const ViewCamera*>& cameras,
                const std::vector<const FeatureMap*>& features,
                const std::vector<DepthMapRef>& depths, int threads);
  // Same points and settings. Float sums depend on their order: merged partials of views split
  // between threads differ (in the last bits) from one aggregator that saw every view, so a
  // result that must not depend on the thread count uses addViews instead.
  void merge(const VoxelAggregator& other);

  std::size_t pointCount() const { return m_points.size(); }
  int channels() const { return m_channels; }
  int viewsAdded() const { return m_viewsAdded; }
  // Per point: sum of samples and number of views that counted (all views for Mean).
  const std::vector<float>& sums() const { return m_sums; }
  const std::vector<int>& counts() const { return m_counts; }
  // Per point per channel: sum / count; 0 where no view counted.
  std::vector<float> mean() const;

 private:
  void checkView(const FeatureMap& features, const DepthMapRef* depth) const;
  // The view's samples for points [begin, end).
  void addSamples(const ViewCamera& camera, const FeatureMap& features, const DepthMapRef* depth,
                  std::size_t begin, std::size_t end);

  std::vector<Eigen::Vector3f> m_points;
  int m_channels;
  Aggregation m_mode;
  float m_tolerance;
  int m_viewsAdded = 0;
  std::vector<float> m_sums;  // float: dinov2 has 1024 channels per point
  std::vector<int> m_counts;
};

// Depth tolerance for the occlusion test: one voxel edge of an N^3 grid over the unit cube.
inline float voxelDepthTolerance(int resolution) { return 1.0f / static_cast<float>(resolution); }

}  // namespace sagrid
