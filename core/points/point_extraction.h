// From a predicted distance field over the occupied voxels to affordance points (normalized
// frame). One instance: the occupied voxel with the smallest predicted distance (paper, III-D).
// A known count: threshold the low-distance voxels and cluster them with k-means (paper).
// Unknown count (beyond the paper): local minima of the field among occupied voxels, non-maximum
// suppression within a radius, only minima predicted closer than a threshold (absolute, or above
// the best minimum) and only basins deep enough (persistence) — calibrated and stored in the
// model card. No torch here.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "core/grid/voxel_grid.h"

namespace sagrid {

// Predicted distance (normalized units) at each occupied voxel.
struct PredictedField {
  int resolution = kDefaultGridResolution;
  std::vector<VoxelIndex> voxels;
  std::vector<float> distances;  // same length as voxels
};

struct ExtractionSettings {
  float maxDistance = 0.04f;      // automatic count: keep minima predicted closer than this
  float nmsRadius = 0.08f;        // automatic count: suppress minima within this of a better one
  float confidenceScale = 0.02f;  // confidence = exp(-predicted distance / scale)
  // Sub-voxel refinement of each minimum: the centroid of the occupied voxels within this many
  // voxels of it, weighted by exp(-(d - d_min) / (half a voxel)). 0 = voxel centres (paper).
  float refineVoxels = 0.0f;
  // Automatic count: maxDistance counts from the best minimum's predicted distance instead of
  // from 0. On real objects the whole field often sits higher than on generated ones (every
  // burner of a real cooker predicted 13-18 cm away, in normalized units), so an absolute
  // threshold keeps only the best one.
  bool maxDistanceAboveBest = false;
  // Automatic count: keep only minima whose basin is at least this deep (normalized units): how
  // far the field rises from the minimum before its basin joins a better one (0-dimensional
  // persistence of the sublevel sets). Noise dimples in a shallow field have almost none.
  float minPersistence = 0.0f;
  // Run the coarse-to-fine second pass (core/annotate/coarse_to_fine.h) for this model unless the
  // caller says otherwise (`train --coarse-to-fine` sets it; the shipped sink.togglebutton card
  // has it on).
  bool coarseToFine = false;
  // The learned point decision also takes candidates from the mesh's crease patches
  // (core/geometry/crease_patches.h: a burner's ring modelled into the hob) for this model. On
  // where leaving one source out shows it helps: the shipped stove cards (resources/models/
  // README.md, session 42); for the sink models more candidates made worse decisions.
  bool creasePatches = false;
};

struct ExtractedPoint {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();  // normalized frame
  float distance = 0;    // predicted distance at the point's best voxel
  float confidence = 0;  // in (0, 1]
};

// A point's confidence from its predicted distance: exp(-distance / confidenceScale), in (0, 1].
float confidenceOf(float distance, const ExtractionSettings& settings);

// Throws InvalidArgument on an empty field or mismatched sizes.
ExtractedPoint argminPoint(const PredictedField& field, const ExtractionSettings& settings);

// `count` instances: the voxels whose predicted distance is below a threshold (the larger of
// twice the spacing of the count-th best local minimum and a few voxels) are clustered with
// k-means (k-means++ seeding, fixed seed, several restarts); each cluster gives its
// distance-weighted centroid. Fewer points when fewer voxels exist.
std::vector<ExtractedPoint> kMeansPoints(const PredictedField& field, int count,
                                         const ExtractionSettings& settings);

// Automatic count (at least one point: the argmin is always kept).
std::vector<ExtractedPoint> autoCountPoints(const PredictedField& field,
                                            const ExtractionSettings& settings);

// Local minima (26-neighbourhood among occupied voxels), best first, as indices into the field.
std::vector<std::size_t> localMinima(const PredictedField& field);

// A local minimum with the depth of its basin: the predicted distance at which, growing the set
// of voxels below a level, its component joins one with a better minimum, minus its own
// distance. The best minimum's basin never joins one: infinite persistence.
struct FieldMinimum {
  std::size_t voxel = 0;  // index into the field
  float persistence = 0;
};
// The local minima of localMinima (same set, same order) with their persistence.
std::vector<FieldMinimum> fieldMinima(const PredictedField& field);

// Chooses maxDistance, maxDistanceAboveBest, minPersistence and nmsRadius maximising the share of
// objects whose automatic count equals the ground-truth count (ties: smaller total count
// difference), over a fixed grid of candidates. `truths[i]` are the ground-truth points (normalized
// frame) of `fields[i]`. Other settings (refinement, confidence scale) are taken from `base`.
ExtractionSettings calibrateExtraction(const std::vector<PredictedField>& fields,
                                       const std::vector<std::vector<Eigen::Vector3f>>& truths,
                                       const ExtractionSettings& base = {});

// The same search with any objective: `cost(i, points)` is what the automatic count's points
// (normalized frame, best first) cost on `fields[i]`; the candidate with the smallest summed cost
// wins (the first one on ties; `cost` must not be negative). The candidates: an absolute or an
// above-the-best threshold, a minimum basin depth, a suppression radius. Returns `base` for no
// fields.
using ExtractionCost = std::function<double(std::size_t, const std::vector<Eigen::Vector3f>&)>;
ExtractionSettings calibrateExtraction(const std::vector<PredictedField>& fields,
                                       const ExtractionCost& cost, const ExtractionSettings& base);

}  // namespace sagrid
