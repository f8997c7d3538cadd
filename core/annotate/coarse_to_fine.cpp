#include "core/annotate/coarse_to_fine.h"

#include <algorithm>

#include "core/common/error.h"
#include "core/features/feature_grid.h"
#include "core/features/feature_pipeline.h"
#include "core/mesh/mesh.h"
#include "core/mesh/mesh_crop.h"

namespace sagrid {

std::optional<Eigen::AlignedBox3f> cropRegion(const ModelPrediction& coarse,
                                              const Normalization& objectNormalization,
                                              const Eigen::AlignedBox3f& objectBounds,
                                              const CoarseToFineOptions& options,
                                              std::string* why) {
  if (coarse.points.empty()) {
    if (why) *why = "no first-pass point";
    return std::nullopt;
  }
  std::vector<Eigen::Vector3f> points;
  for (const auto& p : coarse.points) points.push_back(objectNormalization.toMesh(p.position));
  return regionAround(points, objectBounds, options.margin, options.maxCropShare, why);
}

Eigen::Vector3f cropToObject(const Eigen::Vector3f& cropNormalized, const Normalization& crop,
                             const Normalization& object) {
  return object.toNormalized(crop.toMesh(cropNormalized));
}

ModelPrediction refineInCrop(const model::AffordanceModel& model, const ModelPrediction& coarse,
                             const Mesh& mesh, const FeatureGrid& objectFeatures,
                             const SurfaceScene& scene, const FeatureOptions& featureOptions,
                             InstanceMode mode, int count, int symmetries,
                             const CoarseToFineOptions& options, std::string* why) {
  const auto region =
      cropRegion(coarse, objectFeatures.normalization, mesh.bounds(), options, why);
  if (!region) return coarse;
  const Mesh crop = cropMesh(mesh, *region);
  if (static_cast<int>(crop.triangleCount()) < options.minTriangles) {
    if (why) *why = "the crop holds " + std::to_string(crop.triangleCount()) + " triangles";
    return coarse;
  }
  FeatureGrid cropFeatures;
  try {
    FeatureOptions cropOptions = featureOptions;
    cropOptions.cacheDir.clear();  // the crop is not a file: nothing to key a cache entry on
    cropFeatures = computeFeatures(crop, cropOptions);
  } catch (const Error& error) {
    if (why) *why = std::string("the crop's features failed: ") + error.what();
    return coarse;
  }
  if (cropFeatures.voxels.empty()) {
    if (why) *why = "the crop has no occupied voxel";
    return coarse;
  }
  // The card's count settings are lengths in the object's normalized units: the same physical
  // lengths are longer in the crop's (a burner's neighbour is as far away as before).
  const Normalization& object = objectFeatures.normalization;
  const float distanceScale = object.scale / cropFeatures.normalization.scale;
  ExtractionSettings settings = model.card().extraction;
  settings.maxDistance /= distanceScale;
  settings.nmsRadius /= distanceScale;
  ModelPrediction fine = predictionFromField(model, predictField(model, cropFeatures, symmetries),
                                             cropFeatures, scene, mesh.fileUp, mode, count,
                                             &settings);
  // Back to the object's normalized frame: positions through the mesh frame, distances by the
  // ratio of the two scales.
  for (auto& p : fine.points) {
    p.position = cropToObject(p.position, cropFeatures.normalization, object);
    p.distance *= distanceScale;
  }
  fine.field = coarse.field;
  if (why) why->clear();
  return fine;
}

}  // namespace sagrid
