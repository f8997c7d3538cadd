// Coarse-to-fine prediction for small parts on large objects (a tap on a 2 m counter covers a few
// voxels of the object's 64^3 grid): after the first pass, the region around its points is cut
// out of the mesh (core/mesh/mesh_crop.h), voxelized at the full grid resolution, and the model
// predicts again on the crop, which the 64^3 grid now resolves at the part's scale. The refined
// points are mapped back through the crop's own normalization to the mesh frame — the crop keeps
// the mesh's coordinates, so nothing else changes — and projected onto the whole mesh's surface.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "core/annotate/annotate.h"
#include "core/mesh/mesh_crop.h"

namespace sagrid {

struct Mesh;

struct CoarseToFineOptions {
  // The crop is the box around the first pass's points grown by this share of the object's
  // largest extent on every side.
  float margin = kCropMargin;
  // No second pass when the crop would span more than this share of the object's largest extent
  // (the first pass already saw it at that scale).
  float maxCropShare = kCropMaxShare;
  // No second pass when the crop holds fewer triangles (nothing to see at a finer scale).
  int minTriangles = kCropMinTriangles;
};

// The crop box (z-up mesh frame) around `coarse`'s points, or nullopt with the reason in `why`
// when no second pass should run.
std::optional<Eigen::AlignedBox3f> cropRegion(const ModelPrediction& coarse,
                                              const Normalization& objectNormalization,
                                              const Eigen::AlignedBox3f& objectBounds,
                                              const CoarseToFineOptions& options,
                                              std::string* why = nullptr);

// Points and normals in the object's normalized frame are mapped to the crop's and back exactly
// (up to float rounding): these are the two maps the second pass uses.
Eigen::Vector3f cropToObject(const Eigen::Vector3f& cropNormalized, const Normalization& crop,
                             const Normalization& object);

// The second pass for one model: `coarse` refined on the crop around its points, in the same
// instance mode. Returns `coarse` itself (and the reason in `why`) when the region is too large,
// the crop holds too few triangles, or its features cannot be computed. The result's points and
// their distances are expressed in the object's normalized frame, its field is the coarse one
// (what the GUI shows over the whole object).
ModelPrediction refineInCrop(const model::AffordanceModel& model, const ModelPrediction& coarse,
                             const Mesh& mesh, const FeatureGrid& objectFeatures,
                             const SurfaceScene& scene, const FeatureOptions& featureOptions,
                             InstanceMode mode, int count, int symmetries,
                             const CoarseToFineOptions& options = {}, std::string* why = nullptr);

}  // namespace sagrid
