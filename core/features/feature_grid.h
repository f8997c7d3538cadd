// Per-voxel features and the object-level descriptor of one normalized object: the contract
// between feature extraction (core/features) and the SAGrid model (core/model).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/grid/normalization.h"
#include "core/grid/voxel_grid.h"

namespace sagrid {

struct FeatureGrid {
  std::string backend;        // feature backend name, e.g. "embedded" or "dinov2+trellis"
  std::string configHash;     // hash of the backend's configuration (cache key, model card check)
  int resolution = kDefaultGridResolution;
  int channels = 0;           // per-voxel feature channels (occupancy mask not included)
  std::vector<VoxelIndex> voxels;   // occupied voxels, increasing linear index
  std::vector<float> values;        // voxels.size() * channels, row-major (voxel, channel)
  std::vector<float> descriptor;    // object-level descriptor (paper: mean DINOv2, 1024-d)
  Normalization normalization;      // mesh frame <-> normalized frame of this object

  const float* featuresOf(std::size_t voxel) const { return values.data() + voxel * channels; }
};

}  // namespace sagrid
