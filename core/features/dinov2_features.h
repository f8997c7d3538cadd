// The "dinov2" backend: TRELLIS's feature step (dataset_toolkits/extract_feature.py) on our CPU
// renders — render the TRELLIS views, run DINOv2 on each, sample the 37x37 patch-token maps at
// the projected voxel centres (bilinear), average over views. The object descriptor is the mean
// patch token over all views, weighted by how much of each patch the object covers (background
// patches say nothing about the object).
#pragma once

#include <cstdint>
#include <vector>

#include "core/features/feature_pipeline.h"
#include "core/grid/voxel_grid.h"

namespace sagrid {

struct Mesh;
class SurfaceScene;
class ImageEncoder;

struct EncodedFeatures {
  std::vector<float> values;      // occupied voxels x encoder channels (empty: descriptor only)
  std::vector<float> descriptor;  // encoder channels
};

// Renders `views` TRELLIS views of the normalized mesh at the encoder's size, encodes them in
// batches and aggregates into the occupied voxels of `grid` (skipped when `aggregateVoxels` is
// false, for backends that only need the descriptor).
EncodedFeatures encodeViewsIntoVoxels(const Mesh& normalizedMesh, const SurfaceScene& scene,
                                      const VoxelGrid& grid, std::uint64_t seed, int views,
                                      ImageEncoder& encoder, Aggregation aggregation,
                                      bool aggregateVoxels = true);

}  // namespace sagrid
