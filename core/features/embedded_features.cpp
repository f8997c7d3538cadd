#include "core/features/embedded_features.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/common/elapsed.h"
#include "core/common/log.h"
#include "core/common/thread_count.h"
#include "core/features/embedded_view_encoder.h"
#include "core/features/surface_samples.h"
#include "core/features/voxel_aggregation.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"
#include "core/render/multiview_renderer.h"
#include "core/render/trellis_views.h"

namespace sagrid::embedded {

namespace {
using View = EmbeddedViewEncoder;

// Below this much mask coverage a voxel counts as never seen (its samples are all background).
constexpr float kSeenCoverage = 1e-3f;

float luminance(const float* rgb) { return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]; }

void addHistogram(std::vector<float>& out, const std::vector<float>& values, float lo, float hi) {
  std::vector<float> bins(kHistogramBins, 0.0f);
  for (float v : values) {
    const int b =
        std::clamp(static_cast<int>((v - lo) / (hi - lo) * kHistogramBins), 0, kHistogramBins - 1);
    bins[b] += 1.0f;
  }
  const float total = std::max<float>(1.0f, static_cast<float>(values.size()));
  for (float& b : bins) out.push_back(b / total);
}

// Occupied share of the (2r+1)^3 - 1 neighbours.
float neighbourOccupancy(const VoxelGrid& grid, const VoxelIndex& v, int r) {
  int occupied = 0;
  for (int di = -r; di <= r; ++di)
    for (int dj = -r; dj <= r; ++dj)
      for (int dk = -r; dk <= r; ++dk) {
        if (!di && !dj && !dk) continue;
        const VoxelIndex n{v.i + di, v.j + dj, v.k + dk};
        if (grid.contains(n) && grid.occupied(n)) ++occupied;
      }
  const int side = 2 * r + 1;
  return static_cast<float>(occupied) / static_cast<float>(side * side * side - 1);
}
}  // namespace

std::vector<std::string> channelNames() {
  return {"albedo_r",    "albedo_g",         "albedo_b",           "normal_x",
          "normal_y",    "normal_z",         "visibility",         "top_visibility",
          "height",      "radial",           "area_density",       "occupancy_3",
          "occupancy_5", "normal_variation", "luminance_contrast", "colour_contrast"};
}

Result fromAggregates(const Mesh& mesh, const VoxelGrid& grid, const std::vector<float>& viewSums,
                      int totalViews, int upperViews) {
  const std::vector<VoxelIndex> voxels = grid.occupiedVoxels();
  const std::size_t count = voxels.size();
  const std::vector<VoxelSurfaceStats> surface = voxelSurfaceStats(mesh, grid);
  const std::vector<int> slots = occupiedSlots(grid);
  const float h = 1.0f / grid.resolution();
  Result result;
  result.values.assign(count * kChannelCount, 0.0f);

  int kMin = grid.resolution(), kMax = -1, iMin = grid.resolution(), iMax = -1,
      jMin = grid.resolution(), jMax = -1;
  for (const VoxelIndex& v : voxels) {
    kMin = std::min(kMin, v.k), kMax = std::max(kMax, v.k);
    iMin = std::min(iMin, v.i), iMax = std::max(iMax, v.i);
    jMin = std::min(jMin, v.j), jMax = std::max(jMax, v.j);
  }
  const float axisI = 0.5f * (iMin + iMax), axisJ = 0.5f * (jMin + jMax);
  float maxRadial = 0.0f;
  for (const VoxelIndex& v : voxels)
    maxRadial = std::max(maxRadial, std::hypot(v.i - axisI, v.j - axisJ));

  for (std::size_t p = 0; p < count; ++p) {
    float* f = &result.values[p * kChannelCount];
    const float* s = &viewSums[p * View::kChannelCount];
    const VoxelSurfaceStats& st = surface[p];
    const float coverage = s[View::kMask];
    if (coverage > kSeenCoverage) {
      for (int c = 0; c < 3; ++c) f[kAlbedoR + c] = s[View::kAlbedoR + c] / coverage;
      Eigen::Vector3f n(s[View::kNormalX], s[View::kNormalY], s[View::kNormalZ]);
      if (n.norm() > 1e-6f) n.normalize();
      for (int c = 0; c < 3; ++c) f[kNormalX + c] = n[c];
    } else if (st.area > 0.0f) {
      for (int c = 0; c < 3; ++c) f[kAlbedoR + c] = st.albedo[c] / st.area;
    } else {
      for (int c = 0; c < 3; ++c) f[kAlbedoR + c] = 0.5f;
    }
    for (int c = 0; c < 3; ++c) f[kAlbedoR + c] = std::clamp(f[kAlbedoR + c], 0.0f, 1.0f);
    f[kVisibility] = std::min(1.0f, coverage / std::max(1, totalViews));
    f[kTopVisibility] = std::min(1.0f, s[View::kMaskFromAbove] / std::max(1, upperViews));
    const VoxelIndex& v = voxels[p];
    f[kHeight] = kMax > kMin ? static_cast<float>(v.k - kMin) / (kMax - kMin) : 0.0f;
    f[kRadial] = maxRadial > 0 ? std::hypot(v.i - axisI, v.j - axisJ) / maxRadial : 0.0f;
    f[kAreaDensity] = std::log1p(st.area / (h * h)) / std::log(5.0f);
    f[kOccupancy3] = neighbourOccupancy(grid, v, 1);
    f[kOccupancy5] = neighbourOccupancy(grid, v, 2);
    if (st.area > 0.0f) {
      const auto& t = st.normalTensor;
      Eigen::Matrix3f m;
      m << t[0], t[3], t[4], t[3], t[1], t[5], t[4], t[5], t[2];
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> eig(m, Eigen::EigenvaluesOnly);
      const float trace = m.trace();
      f[kNormalVariation] =
          trace > 0 ? std::clamp(1.5f * (1.0f - eig.eigenvalues()[2] / trace), 0.0f, 1.0f) : 0.0f;
    }
  }

  // Colour against the 5^3 neighbourhood (needs every voxel's albedo first).
  for (std::size_t p = 0; p < count; ++p) {
    float* f = &result.values[p * kChannelCount];
    const VoxelIndex& v = voxels[p];
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    int n = 0;
    for (int di = -2; di <= 2; ++di)
      for (int dj = -2; dj <= 2; ++dj)
        for (int dk = -2; dk <= 2; ++dk) {
          if (!di && !dj && !dk) continue;
          const VoxelIndex q{v.i + di, v.j + dj, v.k + dk};
          if (!grid.contains(q)) continue;
          const int slot = slots[grid.linearIndex(q)];
          if (slot < 0) continue;
          const float* g = &result.values[static_cast<std::size_t>(slot) * kChannelCount];
          sum += Eigen::Vector3f(g[kAlbedoR], g[kAlbedoG], g[kAlbedoB]);
          ++n;
        }
    if (n == 0) continue;
    const Eigen::Vector3f mean = sum / static_cast<float>(n);
    const Eigen::Vector3f own(f[kAlbedoR], f[kAlbedoG], f[kAlbedoB]);
    f[kLuminanceContrast] =
        std::clamp(2.0f * (luminance(own.data()) - luminance(mean.data())), -1.0f, 1.0f);
    f[kColourContrast] = std::min(1.0f, (own - mean).norm());
  }

  // Object descriptor.
  std::vector<float> height, radial, normalZ, lum, sat, vis, topVis;
  Eigen::Vector3f meanAlbedo = Eigen::Vector3f::Zero();
  float meanVariation = 0.0f;
  for (std::size_t p = 0; p < count; ++p) {
    const float* f = &result.values[p * kChannelCount];
    height.push_back(f[kHeight]);
    radial.push_back(f[kRadial]);
    if (f[kVisibility] > 0.0f) normalZ.push_back(f[kNormalZ]);
    lum.push_back(luminance(f + kAlbedoR));
    const float mx = std::max({f[kAlbedoR], f[kAlbedoG], f[kAlbedoB]});
    const float mn = std::min({f[kAlbedoR], f[kAlbedoG], f[kAlbedoB]});
    sat.push_back(mx > 1e-6f ? (mx - mn) / mx : 0.0f);
    vis.push_back(f[kVisibility]);
    topVis.push_back(f[kTopVisibility]);
    meanAlbedo += Eigen::Vector3f(f[kAlbedoR], f[kAlbedoG], f[kAlbedoB]);
    meanVariation += f[kNormalVariation];
  }
  std::vector<float>& d = result.descriptor;
  addHistogram(d, height, 0.0f, 1.0f);
  addHistogram(d, radial, 0.0f, 1.0f);
  addHistogram(d, normalZ, -1.0f, 1.0f);
  addHistogram(d, lum, 0.0f, 1.0f);
  addHistogram(d, sat, 0.0f, 1.0f);
  addHistogram(d, vis, 0.0f, 1.0f);
  addHistogram(d, topVis, 0.0f, 1.0f);
  const Eigen::AlignedBox3f box = mesh.bounds();
  Eigen::Vector3f extent = box.isEmpty() ? Eigen::Vector3f::Zero() : Eigen::Vector3f(box.sizes());
  const float largest = std::max(1e-9f, extent.maxCoeff());
  d.push_back(std::max(extent.x(), extent.y()) / largest);
  d.push_back(std::min(extent.x(), extent.y()) / largest);
  d.push_back(extent.z() / largest);
  const float res = static_cast<float>(grid.resolution());
  d.push_back(std::min(1.0f, static_cast<float>(count) / (6.0f * res * res)));
  const float denom = std::max<float>(1.0f, static_cast<float>(count));
  for (int c = 0; c < 3; ++c) d.push_back(meanAlbedo[c] / denom);
  d.push_back(meanVariation / denom);
  return result;
}

Result compute(const Mesh& mesh, const SurfaceScene& scene, const VoxelGrid& grid,
               std::uint64_t seed, const Settings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ViewCamera> cameras = trellisViews(settings.views, seed);
  const EmbeddedViewEncoder encoder(settings.renderSize);
  std::vector<Eigen::Vector3f> points;
  for (const VoxelIndex& v : grid.occupiedVoxels())
    points.push_back(voxelCenter(v, grid.resolution()));

  const int threads = settings.threads > 0 ? settings.threads : defaultThreadCount();
  VoxelAggregator aggregator(std::move(points), View::kChannelCount, settings.aggregation,
                             voxelDepthTolerance(grid.resolution()));
  // Views are rendered a batch at a time on every worker, then added to the one aggregator in
  // view order with the points split between the workers: every voxel sums its views in the same
  // order whatever the thread count, so the features (and the points predicted from them) are
  // bit for bit those of a one-thread run. (Per-thread partial sums merged at the end differed
  // in the last bits, and a near-tie between field minima moved a point by a whole part: issue
  // 42.) Batches are large enough that a slow view rarely leaves workers waiting at a batch's
  // end; a view held for its batch costs about 0.3 MB at the default 96 px.
  const int batch = std::min(static_cast<int>(cameras.size()), std::clamp(8 * threads, 32, 64));
  std::vector<FeatureMap> maps(static_cast<std::size_t>(batch));
  std::vector<std::vector<float>> depths(maps.size());
  const MultiViewRenderer renderer(mesh, scene);
  for (std::size_t first = 0; first < cameras.size(); first += static_cast<std::size_t>(batch)) {
    const std::size_t n = std::min(static_cast<std::size_t>(batch), cameras.size() - first);
    const std::vector<ViewCamera> batchCameras(cameras.begin() + first,
                                               cameras.begin() + first + n);
    std::vector<DepthMapRef> depthRefs(n);
    renderer.renderEach(batchCameras, settings.renderSize, threads,
                        [&](int index, int, const RenderedView& view) {
                          encoder.encodeOne(view, batchCameras[index], maps[index]);
                          depths[index] = view.depth;  // the view's buffers are reused
                          depthRefs[index] = {view.width, view.height, depths[index].data()};
                        });
    std::vector<const ViewCamera*> cameraPtrs;
    std::vector<const FeatureMap*> mapPtrs;
    for (std::size_t i = 0; i < n; ++i) {
      cameraPtrs.push_back(&batchCameras[i]);
      mapPtrs.push_back(&maps[i]);
    }
    aggregator.addViews(cameraPtrs, mapPtrs, depthRefs, threads);
  }
  const int upper = static_cast<int>(std::count_if(
      cameras.begin(), cameras.end(), [](const ViewCamera& c) { return c.position().z() > 0.0f; }));
  const auto viewsDone = std::chrono::steady_clock::now();
  Result result =
      fromAggregates(mesh, grid, aggregator.sums(), static_cast<int>(cameras.size()), upper);
  logger()->debug("embedded features: views {:.3f} s, voxel channels {:.3f} s",
                  std::chrono::duration<double>(viewsDone - start).count(),
                  secondsSince(viewsDone));
  return result;
}

}  // namespace sagrid::embedded
