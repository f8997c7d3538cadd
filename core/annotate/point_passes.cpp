#include "core/annotate/point_passes.h"

#include <algorithm>
#include <future>

#include "core/annotate/category_evidence.h"
#include "core/annotate/coarse_to_fine.h"
#include "core/annotate/model_set.h"
#include "core/annotate/point_scorer.h"
#include "core/geometry/crease_patches.h"
#include "core/geometry/material_parts.h"
#include "core/geometry/surface_openness.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

// Where a normalized point meets the z-up mesh of `scene`, in normalized units.
SurfaceContact surfaceContact(const SurfaceScene& scene, const Normalization& normalization,
                              const Eigen::Vector3f& at) {
  // Just off the surface: a quarter of a 64-voxel grid's cell.
  constexpr float kOffset = 0.004f;
  const ClosestPoint closest = scene.closestPoint(normalization.toMesh(at));
  const float scale = normalization.scale;
  const SurfaceOpenness open = surfaceOpenness(scene, closest, kOffset / scale);
  return {closest.normal, closest.distance * scale, open.openness, open.below * scale,
          open.above * scale};
}

// How one model runs: a type in `counts` takes InstanceMode::Count with its count (k-means), and
// Count without one falls back to Auto.
struct ModelRun {
  InstanceMode mode = InstanceMode::Auto;
  int count = 1;
};

ModelRun modelRunOf(const std::string& type, InstanceMode mode,
                    const std::map<std::string, int>& counts) {
  const auto count = counts.find(type);
  if (count != counts.end()) return {InstanceMode::Count, count->second};
  return {mode == InstanceMode::Count ? InstanceMode::Auto : mode, 1};
}

// A model's points before the learned decision: its field and instances, then the
// coarse-to-fine crop.
ModelPrediction locateWithModel(const model::AffordanceModel& model, const ObjectForPasses& object,
                                const PassOptions& passes, ModelRun run) {
  ModelPrediction p = predictWithModel(model, object.features, object.scene, object.mesh.fileUp,
                                       run.mode, run.count, nullptr, passes.symmetries);
  if (passes.coarseToFine.value_or(model.card().extraction.coarseToFine))
    p = refineInCrop(model, p, object.mesh, object.features, object.scene, object.featureOptions,
                     run.mode, run.count, passes.symmetries);
  return p;
}

}  // namespace

std::vector<ConnectedPart> normalizedParts(std::vector<ConnectedPart> parts,
                                           const Normalization& normalization) {
  for (auto& part : parts) {
    part.area *= normalization.scale * normalization.scale;
    part.spread *= normalization.scale;
    part.centroid = normalization.toNormalized(part.centroid);
    if (!part.box.isEmpty())
      part.box = Eigen::AlignedBox3f(normalization.toNormalized(part.box.min()),
                                     normalization.toNormalized(part.box.max()));
  }
  return parts;
}

PassOptions withLearnedDecision(PassOptions passes, const ModelSet& models) {
  passes.scorer = passes.learnedDecision ? models.pointScorer() : nullptr;
  if (passes.scorer)
    for (const auto& name : passes.scorer->passesOff)
      for (const auto& pass : namedPasses())
        if (name == pass.name) pass.switchOff(passes);
  return passes;
}

CategoryPoints predictCategoryPoints(const std::vector<const model::AffordanceModel*>& models,
                                     const ObjectForPasses& object, const PassOptions& passes,
                                     InstanceMode mode, const std::map<std::string, int>& counts,
                                     const std::function<void(std::size_t)>& beforeModel) {
  const Mesh& mesh = object.mesh;
  const FeatureGrid& features = object.features;
  const SurfaceScene& scene = object.scene;
  // Each model's field, instances and crop read nothing of the other models, so the models run
  // side by side, and the mesh's parts beside them; each step gives the same numbers on any
  // thread.
  std::vector<std::future<ModelPrediction>> located;
  for (std::size_t m = 0; m < models.size(); ++m) {
    if (beforeModel) beforeModel(m);
    located.push_back(std::async(std::launch::async, locateWithModel, std::cref(*models[m]),
                                 std::cref(object), std::cref(passes),
                                 modelRunOf(models[m]->card().type, mode, counts)));
  }
  const bool decide = (passes.scorer || passes.keepCandidates) && mode == InstanceMode::Auto &&
                      counts.empty();
  // The mesh's parts, and with its crease patches where a model's card asks for them.
  std::vector<ConnectedPart> parts, partsAndPatches;
  if (decide) {
    parts = normalizedParts(object.meshParts ? *object.meshParts : connectedAndMaterialParts(mesh),
                            features.normalization);
    if (std::any_of(models.begin(), models.end(),
                    [](const auto* m) { return m->card().extraction.creasePatches; })) {
      partsAndPatches = parts;
      appendNewParts(partsAndPatches, normalizedParts(creasePatches(mesh), features.normalization),
                     &ConnectedPart::byCrease);
    }
  }
  CategoryPoints out;
  for (auto& model : located) out.predictions.push_back(model.get());
  out.evidence = affordanceEvidence(out.predictions);
  if (!decide) return out;
  // The learned decision: it chooses among the count's points, the field's minima and the small
  // parts (and crease patches, where the model's card says so).
  std::vector<std::vector<PointCandidate>> found(out.predictions.size());
  std::vector<const ModelPointScorer*> scorers(out.predictions.size(), nullptr);
  std::vector<std::vector<float>> descriptions(out.predictions.size());
  for (std::size_t m = 0; m < out.predictions.size(); ++m) {
    ModelPrediction& p = out.predictions[m];
    const auto& card = models[m]->card();
    std::vector<const PredictedField*> others;
    for (std::size_t o = 0; o < out.predictions.size(); ++o)
      if (o != m) others.push_back(&out.predictions[o].field);
    found[m] = pointCandidates(
        p.field, p.points, card.extraction.creasePatches ? partsAndPatches : parts,
        [&](const Eigen::Vector3f& at) {
          return surfaceContact(scene, features.normalization, at);
        },
        others);
    scorers[m] = passes.scorer ? passes.scorer->forModel(card.name) : nullptr;
    if (scorers[m]) descriptions[m] = countDescription(*scorers[m], found[m]);
  }
  // Each model's count also reads the category's other models (a knob per burner).
  for (std::size_t m = 0; m < out.predictions.size(); ++m) {
    std::vector<std::vector<float>> otherModels;
    for (std::size_t o = 0; o < out.predictions.size(); ++o)
      if (o != m) otherModels.push_back(descriptions[o]);
    if (scorers[m] && !found[m].empty())
      setPoints(out.predictions[m],
                scoredPoints(*scorers[m], found[m], models[m]->card().extraction, otherModels),
                features, scene, mesh.fileUp);
    if (passes.keepCandidates) out.candidates.push_back(std::move(found[m]));
  }
  return out;
}

}  // namespace sagrid
