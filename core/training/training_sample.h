// What one training step sees of an object: its occupied voxels with features, the object
// descriptor, and the ground-truth affordance points of the trained type in the normalized frame;
// plus the regression target D(v) = log(1 + ||v - c*||) to the nearest ground-truth point
// (paper, Section III-C). Plain C++: the trainer turns samples into tensors.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/features/feature_grid.h"
#include "core/grid/voxel_grid.h"
#include "core/labels/labels.h"

namespace sagrid {

struct TrainingSample {
  std::string id;
  int resolution = kDefaultGridResolution;
  int channels = 0;
  std::vector<VoxelIndex> voxels;
  std::vector<float> features;  // voxels.size() * channels
  std::vector<float> descriptor;
  std::vector<Eigen::Vector3f> targets;  // ground truth, normalized frame (z up)
};

// The ground-truth points of `type` in `labels` (mesh file coordinates, object.up) mapped into
// the normalized frame of `features`. Empty when the object has none of that type.
std::vector<Eigen::Vector3f> normalizedTargets(const ObjectLabels& labels, const std::string& type,
                                               const FeatureGrid& features);

TrainingSample makeTrainingSample(std::string id, const FeatureGrid& features,
                                  std::vector<Eigen::Vector3f> targets);

// D(v) per voxel of the sample (distances between voxel centres and targets, normalized frame).
// `cap` > 0 clips the distance first (log(1 + min(d, cap))): beyond the network's receptive field
// the distance to the nearest instance cannot be seen locally, and a capped target keeps the loss
// on what can (an option beyond the paper; 0 = the paper's target).
std::vector<float> distanceTargets(const TrainingSample& sample, float cap = 0.0f);

}  // namespace sagrid
