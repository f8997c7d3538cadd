// The sequence that turns an object's features into the points of every model of its category:
// per model the field (averaged over symmetric copies), the instances, the coarse-to-fine crop,
// then the automatic count's passes (mirror pairs, repeated parts, spout outlets), the printed
// marks, across the models the part-ownership pass, and last, where the models folder has a point
// scorer (core/annotate/point_scorer.h), its choice among the point candidates. `annotate` and
// `eval` both call it, so what eval measures is what annotate writes; PassOptions switches the
// steps off one by one.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/annotate/annotate.h"
#include "core/features/printed_marks.h"
#include "core/points/point_candidates.h"

namespace sagrid {

struct Mesh;

// The object as the models and passes see it: the mesh (file frame, z-up copy used for the
// passes), its features and surface, and the feature options the crop pass voxelizes with.
struct ObjectForPasses {
  const Mesh& mesh;
  const FeatureGrid& features;
  const SurfaceScene& scene;
  const FeatureOptions& featureOptions;
};

struct CategoryPoints {
  std::vector<ModelPrediction> predictions;  // one per model, in the models' order
  PrintedMarks printed;                      // what the texture pass found (empty when off)
  // Per model, its point candidates after the passes (PassOptions::keepCandidates; else empty).
  std::vector<std::vector<PointCandidate>> candidates;
  // The category's evidence (category_evidence.h): the best point confidence of the count and its
  // passes, before a learned decision chooses; the evidence gate was fitted on it.
  double evidence = 0;
};

class ModelSet;

// `passes` with `models`' learned point decision (ModelSet::pointScorer) when
// passes.learnedDecision is on, and the passes it learned without switched off; without it, or
// off, no scorer and the passes as given.
PassOptions withLearnedDecision(PassOptions passes, const ModelSet& models);

// Runs `models` (one category's, `category`) on `object`. `mode` is the instance mode; a type in
// `counts` takes InstanceMode::Count with its count (k-means), and Count without one falls back
// to Auto. The automatic count's passes run on Auto models only (spout outlets also with a known
// count), part ownership only when every model is Auto. `beforeModel(i)` is called before model
// i runs (progress, cancellation), when given.
CategoryPoints predictCategoryPoints(const std::vector<const model::AffordanceModel*>& models,
                                     const std::string& category, const ObjectForPasses& object,
                                     const PassOptions& passes, InstanceMode mode,
                                     const std::map<std::string, int>& counts = {},
                                     const std::function<void(std::size_t)>& beforeModel = {});

}  // namespace sagrid
