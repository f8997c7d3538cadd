// A per-voxel distance field for one affordance type, as the viewport shows it: the voxels that
// carry a value (usually the occupied surface voxels of the 64^3 grid, or all of it) and each
// one's distance to the nearest affordance point, in mesh-frame units (metres for metric assets).
// Predicted fields come from the model; fields "of the labels" are computed from the points.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/grid/normalization.h"
#include "core/grid/voxel_grid.h"

namespace sagrid::ui {

struct DistanceField {
  std::string type;  // affordance type, e.g. "heatsource"
  int resolution = kDefaultGridResolution;
  Normalization normalization;  // normalized grid frame <-> z-up mesh frame
  std::vector<VoxelIndex> voxels;
  std::vector<float> distances;  // per voxel, mesh-frame units

  float voxelSize() const { return normalization.lengthToMesh(1.0f / float(resolution)); }
  Eigen::Vector3f center(std::size_t i) const {
    return normalization.toMesh(voxelCenter(voxels[i], resolution));
  }
};

// Distance from each voxel centre to the nearest of `points` (z-up mesh frame). With no points
// every distance is +infinity (the voxels still show as "far").
DistanceField distanceFieldFromPoints(const std::string& type,
                                      const std::vector<VoxelIndex>& voxels, int resolution,
                                      const Normalization& normalization,
                                      const std::vector<Eigen::Vector3f>& points);

// Every voxel of the grid (resolution^3), for worst-case rendering benchmarks.
std::vector<VoxelIndex> allVoxels(int resolution);

}  // namespace sagrid::ui
