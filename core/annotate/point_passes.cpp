#include "core/annotate/point_passes.h"

#include <future>

#include "core/annotate/category_rules.h"
#include "core/annotate/category_evidence.h"
#include "core/annotate/coarse_to_fine.h"
#include "core/annotate/mirror_pairs_pass.h"
#include "core/annotate/model_set.h"
#include "core/annotate/part_ownership_pass.h"
#include "core/annotate/point_scorer.h"
#include "core/annotate/printed_marks_pass.h"
#include "core/annotate/repeated_parts_pass.h"
#include "core/annotate/spout_controls_pass.h"
#include "core/annotate/spout_outlet_pass.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"
#include "core/points/surface_projection.h"

namespace sagrid {

namespace {

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

// A model's points before the passes that read other models' points: its field and instances,
// then the coarse-to-fine crop.
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

PassOptions withLearnedDecision(PassOptions passes, const ModelSet& models) {
  passes.scorer = passes.learnedDecision ? models.pointScorer() : nullptr;
  if (passes.scorer)
    for (const auto& name : passes.scorer->passesOff)
      for (const auto& pass : namedPasses())
        if (name == pass.name) pass.switchOff(passes);
  return passes;
}

CategoryPoints predictCategoryPoints(const std::vector<const model::AffordanceModel*>& models,
                                     const std::string& category, const ObjectForPasses& object,
                                     const PassOptions& passes, InstanceMode mode,
                                     const std::map<std::string, int>& counts,
                                     const std::function<void(std::size_t)>& beforeModel) {
  const Mesh& mesh = object.mesh;
  const FeatureGrid& features = object.features;
  const SurfaceScene& scene = object.scene;
  const CategoryRules rules = categoryRulesFor(category);
  // Each model's field, instances and crop read nothing of the other models, so the models run
  // side by side, and the mesh's marks and parts beside them; each step gives the same numbers
  // on any thread. The passes that read other models' points then run in the models' order.
  std::vector<ModelRun> runs;
  std::vector<std::future<ModelPrediction>> located;
  for (std::size_t m = 0; m < models.size(); ++m) {
    if (beforeModel) beforeModel(m);
    runs.push_back(modelRunOf(models[m]->card().type, mode, counts));
    located.push_back(std::async(std::launch::async, locateWithModel, std::cref(*models[m]),
                                 std::cref(object), std::cref(passes), runs.back()));
  }
  CategoryPoints out;
  if (passes.printedMarks) out.printed = printedMarksOf(mesh, category);
  const bool candidates = passes.scorer || passes.keepCandidates;
  const std::vector<ConnectedPart> parts =
      passes.repeatedParts || passes.partOwnership || passes.spoutControls || candidates
          ? normalizedParts(mesh, features.normalization)
          : std::vector<ConnectedPart>{};
  for (std::size_t m = 0; m < models.size(); ++m) {
    const auto& model = *models[m];
    const auto& card = model.card();
    const InstanceMode modelMode = runs[m].mode;
    ModelPrediction p = located[m].get();
    if (passes.mirrorPairs && modelMode == InstanceMode::Auto)
      applyMirrorPairs(p, features, scene, mesh.fileUp, card.extraction,
                       passes.anchoredPairs ? mirrorAnchors(out.predictions, p.type)
                                            : std::vector<Eigen::Vector3f>{});
    if (passes.spoutControls && modelMode == InstanceMode::Auto)
      applySpoutControls(p, parts, mirrorAnchors(out.predictions, p.type), features, scene,
                         mesh.fileUp, card.extraction, rules.spoutControls);
    if (passes.repeatedParts && modelMode == InstanceMode::Auto)
      applyRepeatedParts(p, parts, features, scene, mesh.fileUp, card.extraction,
                         rules.repeatedParts);
    if (passes.spoutOutlets && modelMode != InstanceMode::Single)
      applySpoutOutlets(p, features, scene, mesh.fileUp, card.extraction);
    const MarksForType marks = printedMarksFor(out.printed, category, p.type);
    applyPrintedMarks(model, p, marks, features, scene, mesh.fileUp, modelMode, runs[m].count);
    out.predictions.push_back(std::move(p));
  }
  if (passes.partOwnership && mode == InstanceMode::Auto && counts.empty())
    applyPartOwnership(out.predictions, parts, features, scene, mesh.fileUp, rules.partOwnership);
  // Burner caps once every part has its owner: a heat-source point on a knob that a knob row owns
  // is gone by then, and a cap that holds another type's point gets none.
  if (passes.repeatedParts && rules.burnerCaps && mode == InstanceMode::Auto && counts.empty())
    for (std::size_t m = 0; m < out.predictions.size(); ++m)
      if (out.predictions[m].type == "heatsource")
        applyRepeatedParts(out.predictions[m], parts, features, scene, mesh.fileUp,
                           models[m]->card().extraction, *rules.burnerCaps,
                           pointsOfOtherTypes(out.predictions, m));
  out.evidence = affordanceEvidence(out.predictions);
  // The learned decision last: it chooses among the passes' points, the field's minima and the
  // small parts.
  if (candidates && mode == InstanceMode::Auto && counts.empty())
    for (std::size_t m = 0; m < out.predictions.size(); ++m) {
      ModelPrediction& p = out.predictions[m];
      auto found = pointCandidates(p.field, p.points, parts, [&](const Eigen::Vector3f& at) {
        const SurfacePoint s = projectToSurface(at, features.normalization, scene, mesh.fileUp);
        return SurfaceContact{fileToZUpRotation(mesh.fileUp) * s.normal,
                              s.moved * features.normalization.scale};
      });
      const ModelPointScorer* scorer =
          passes.scorer ? passes.scorer->forModel(models[m]->card().name) : nullptr;
      if (scorer && !found.empty())
        setPoints(p, scoredPoints(*scorer, found, models[m]->card().extraction), features, scene,
                  mesh.fileUp);
      if (passes.keepCandidates) out.candidates.push_back(std::move(found));
    }
  return out;
}

}  // namespace sagrid
