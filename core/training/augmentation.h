// Training augmentation of a sparse voxel sample (paper, Section III-C): smooth warps, 90-degree
// rotations about z, reflections across x and y, random translations. Voxels, ground-truth points
// and vector-valued feature channels (normals) move together, so the target field stays exact.
#pragma once

#include <Eigen/Core>
#include <array>
#include <random>
#include <vector>

#include "core/training/training_sample.h"

namespace sagrid {

struct Augmentation {
  int quarterTurns = 0;  // about the z axis through the grid centre, counter-clockwise
  bool flipX = false;    // x -> -x (applied after the rotation)
  bool flipY = false;
  Eigen::Vector3i shift = Eigen::Vector3i::Zero();  // whole voxels, applied last
  // Smooth warp p -> p + sum_m amplitude_m * sin(2 pi frequency_m . p + phase_m) (normalized
  // frame), applied first. Empty = no warp.
  struct WarpWave {
    Eigen::Vector3f amplitude = Eigen::Vector3f::Zero();
    Eigen::Vector3f frequency = Eigen::Vector3f::Zero();
    float phase = 0;
  };
  std::vector<WarpWave> warp;

  Eigen::Vector3f warpPoint(const Eigen::Vector3f& p) const;
};

struct AugmentationRanges {
  bool rotate = true;
  bool reflect = true;
  bool translate = true;
  float warpVoxels = 1.5f;  // largest warp displacement, in voxels (0 = no warp)
  int warpWaves = 3;
};

// Draws an augmentation; the shift keeps the (rotated) sample's voxels inside the grid.
Augmentation randomAugmentation(const TrainingSample& sample, const AugmentationRanges& ranges,
                                std::mt19937& rng);

// Applies `a`; voxels that the warp maps into the same cell are merged (features averaged,
// vector channels renormalised by the average). Output voxels are in increasing linear order.
TrainingSample augment(const TrainingSample& sample, const Augmentation& a,
                       const std::vector<std::array<int, 3>>& vectorChannels);

}  // namespace sagrid
