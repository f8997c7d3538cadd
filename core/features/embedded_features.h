// The embedded feature backend: per-voxel features and an object descriptor computed on the CPU
// in about a second, with no download. Designed for finding affordances on real meshes:
//  - what the surface looks like from outside (TRELLIS-style multi-view aggregation of the
//    render buffers, occlusion-aware): visible albedo, visible normal, how many views see the
//    voxel, how many of the views from above see it (burner tops and basin interiors are seen
//    from above only; hidden inner shells are seen from nowhere);
//  - where the voxel sits in the object: relative height, distance from the vertical axis;
//  - local shape: surface area in the voxel, occupancy of the 3^3 and 5^3 neighbourhoods (knobs,
//    spouts and handles are thin protrusions with low occupancy around them), normal variation;
//  - colour against its surroundings (burner zones and buttons differ in colour from the panel).
// Every channel is in about [0, 1] (normals and signed contrast in [-1, 1]).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/features/feature_pipeline.h"
#include "core/grid/voxel_grid.h"

namespace sagrid {

struct Mesh;
class SurfaceScene;

namespace embedded {
enum Channel {
  kAlbedoR = 0,
  kAlbedoG,
  kAlbedoB,  // mean visible albedo (surface albedo where never seen)
  kNormalX,
  kNormalY,
  kNormalZ,            // mean visible normal, unit (0 where never seen)
  kVisibility,         // share of all views that see the voxel
  kTopVisibility,      // share of the views from above that see it
  kHeight,             // (z - zmin) / (zmax - zmin) over occupied voxels
  kRadial,             // distance from the vertical bbox axis / its maximum
  kAreaDensity,        // log(1 + area / voxel face) / log(5)
  kOccupancy3,         // occupied share of the 26 neighbours
  kOccupancy5,         // occupied share of the 124 neighbours in 5^3
  kNormalVariation,    // 1.5 (1 - largest eigenvalue share of sum n n^T)
  kLuminanceContrast,  // 2 (luminance - mean luminance of 5^3 neighbours), clamped
  kColourContrast,     // |rgb - mean rgb of 5^3 neighbours|, clamped to 1
  kChannelCount
};
static_assert(kChannelCount == kEmbeddedChannels, "embedded channel count is part of the contract");

// Descriptor layout (kEmbeddedDescriptorSize = 64): 8-bin histograms (each sums to 1) of voxel
// height, radial distance, visible normal z, luminance, saturation, visibility, top visibility;
// then sorted horizontal extents and the vertical extent (/ largest), surface-voxel fraction,
// mean albedo RGB, mean normal variation.
constexpr int kHistogramBins = 8;

std::vector<std::string> channelNames();

struct Settings {
  int views = 150;
  int renderSize = 96;
  Aggregation aggregation = Aggregation::OcclusionAware;
  int threads = 0;  // 0 = all hardware threads
};

struct Result {
  std::vector<float> values;      // occupied voxels x kChannelCount
  std::vector<float> descriptor;  // kEmbeddedDescriptorSize
};

// `normalizedMesh` in the normalized frame, `scene` built from it, `grid` its voxelization,
// `seed` for the view offsets (from the mesh's sha256).
Result compute(const Mesh& normalizedMesh, const SurfaceScene& scene, const VoxelGrid& grid,
               std::uint64_t seed, const Settings& settings);

// The channels and descriptor from aggregated view statistics (exposed for tests): `viewSums`
// is occupied voxels x EmbeddedViewEncoder::kChannelCount sums over the views that counted,
// `totalViews` all views, `upperViews` those whose camera is above the object's centre.
Result fromAggregates(const Mesh& normalizedMesh, const VoxelGrid& grid,
                      const std::vector<float>& viewSums, int totalViews, int upperViews);

}  // namespace embedded
}  // namespace sagrid
