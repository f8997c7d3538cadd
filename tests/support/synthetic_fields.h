// Predicted distance fields with known minima, for tests of point extraction and count fitting.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/features/feature_grid.h"
#include "core/points/point_extraction.h"

namespace sagrid::test {

constexpr int kPlateResolution = 32;

// A flat plate of occupied voxels (k = 10) of a kPlateResolution grid whose field is the distance
// to the nearest of `centres` plus uniform noise in [-noise, noise] (clamped at 0).
PredictedField plateField(const std::vector<Eigen::Vector3f>& centres, float noise = 0.0f,
                          unsigned seed = 1);

// The same plate whose field is min over centres of (distance to centre c + offsets[c]): minima
// of different depths (a spurious minimum is a centre that is not in the ground truth).
PredictedField plateFieldWithOffsets(const std::vector<Eigen::Vector3f>& centres,
                                     const std::vector<float>& offsets);

// A field over the occupied voxels of `grid`: min over centres (mesh frame) of the normalized
// distance to centre c plus offsets[c].
PredictedField fieldTowards(const FeatureGrid& grid, const std::vector<Eigen::Vector3f>& centres,
                            const std::vector<float>& offsets);

// The point at `p` (normalized frame) as the count would give it: the field's distance at its
// voxel (0 when that voxel is not in the field), confidence 1.
ExtractedPoint pointOnField(const PredictedField& field, const Eigen::Vector3f& p);

// The centre of plate voxel (i, j) in the normalized frame.
Eigen::Vector3f onPlate(int i, int j);

// Five burners on the plate: the four corners' neighbourhoods and the centre.
std::vector<Eigen::Vector3f> fiveBurnersOnPlate();

// Distance from `p` to the nearest extracted point (1e9 for none).
float nearestExtracted(const std::vector<ExtractedPoint>& points, const Eigen::Vector3f& p);

}  // namespace sagrid::test
