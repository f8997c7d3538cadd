#include "core/training/training_sample.h"

#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

std::vector<Eigen::Vector3f> normalizedTargets(const ObjectLabels& labels, const std::string& type,
                                               const FeatureGrid& features) {
  const UpAxis up = upAxisOrZ(labels.object.up);
  std::vector<Eigen::Vector3f> points;
  for (const auto* a : labels.ofType(type))
    points.push_back(features.normalization.toNormalized(fileToZUp(a->position, up)));
  return points;
}

TrainingSample makeTrainingSample(std::string id, const FeatureGrid& f,
                                  std::vector<Eigen::Vector3f> targets) {
  TrainingSample s;
  s.id = std::move(id);
  s.resolution = f.resolution;
  s.channels = f.channels;
  s.voxels = f.voxels;
  s.features = f.values;
  s.descriptor = f.descriptor;
  s.targets = std::move(targets);
  if (s.features.size() != s.voxels.size() * static_cast<std::size_t>(s.channels))
    throw InvalidArgument("features of " + s.id + ": value count does not match voxels x channels");
  return s;
}

std::vector<float> distanceTargets(const TrainingSample& s, float cap) {
  if (s.targets.empty()) throw InvalidArgument(s.id + ": no ground-truth points for the target");
  std::vector<float> d(s.voxels.size());
  for (std::size_t v = 0; v < s.voxels.size(); ++v) {
    const Eigen::Vector3f c = voxelCenter(s.voxels[v], s.resolution);
    float best = std::numeric_limits<float>::max();
    for (const auto& t : s.targets) best = std::min(best, (c - t).norm());
    d[v] = std::log1p(cap > 0 ? std::min(best, cap) : best);
  }
  return d;
}

}  // namespace sagrid
