#include "core/annotate/point_passes.h"

#include "core/annotate/category_rules.h"
#include "core/annotate/coarse_to_fine.h"
#include "core/annotate/mirror_pairs_pass.h"
#include "core/annotate/part_ownership_pass.h"
#include "core/annotate/printed_marks_pass.h"
#include "core/annotate/repeated_parts_pass.h"
#include "core/annotate/spout_controls_pass.h"
#include "core/annotate/spout_outlet_pass.h"
#include "core/annotate/touch_keys_pass.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"

namespace sagrid {

CategoryPoints predictCategoryPoints(const std::vector<const model::AffordanceModel*>& models,
                                     const std::string& category, const ObjectForPasses& object,
                                     const PassOptions& passes, InstanceMode mode,
                                     const std::map<std::string, int>& counts,
                                     const std::function<void(std::size_t)>& beforeModel) {
  const Mesh& mesh = object.mesh;
  const FeatureGrid& features = object.features;
  const SurfaceScene& scene = object.scene;
  const CategoryRules rules = categoryRulesFor(category);
  CategoryPoints out;
  if (passes.printedMarks) out.printed = printedMarksOf(mesh, category);
  const std::vector<ConnectedPart> parts =
      passes.repeatedParts || passes.partOwnership || passes.touchKeys || passes.spoutControls
          ? normalizedParts(mesh, features.normalization)
          : std::vector<ConnectedPart>{};
  if (passes.touchKeys)
    out.touchKeys =
        touchKeysOf(category, parts, scene, features.normalization, features.resolution);
  for (std::size_t m = 0; m < models.size(); ++m) {
    if (beforeModel) beforeModel(m);
    const auto& model = *models[m];
    const auto& card = model.card();
    const auto count = counts.find(card.type);
    InstanceMode modelMode = mode;
    int n = 1;
    if (count != counts.end())
      modelMode = InstanceMode::Count, n = count->second;
    else if (modelMode == InstanceMode::Count)
      modelMode = InstanceMode::Auto;
    ModelPrediction p = predictWithModel(model, features, scene, mesh.fileUp, modelMode, n, nullptr,
                                         passes.symmetries);
    if (passes.coarseToFine.value_or(card.extraction.coarseToFine))
      p = refineInCrop(model, p, mesh, features, scene, object.featureOptions, modelMode, n,
                       passes.symmetries);
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
    MarksForType marks = printedMarksFor(out.printed, category, p.type);
    if (marks.circles.empty()) marks = touchKeysFor(out.touchKeys, p.type);
    applyPrintedMarks(model, p, marks, features, scene, mesh.fileUp, modelMode, n);
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
  return out;
}

}  // namespace sagrid
