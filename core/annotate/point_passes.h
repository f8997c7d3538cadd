// The sequence that turns an object's features into the points of every model of its category:
// per model the field (averaged over symmetric copies), the instances, the coarse-to-fine crop,
// and last, where the models folder has a point scorer (core/annotate/point_scorer.h), its choice
// among the point candidates (the field's minima, the count's points, the mesh's small parts).
// `annotate` and `eval` both call it, so what eval measures is what annotate writes; PassOptions
// switches the steps off one by one.
//
// The hand-set passes that ran between the count and the decision (mirror pairs, repeated parts
// and burner caps, spout controls and outlets, part ownership, printed marks) were removed in
// session 33: under the learned decision, each one on alone, left out by source, needed more
// curator edits on the 13 wild-pool repositories no pass was made on than all of them off
// (tests/benchmarks/pass_ablation.sh at commit 4e1928e).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/annotate/annotate.h"
#include "core/points/point_candidates.h"

namespace sagrid {

struct Mesh;

// The object as the models see it: the mesh (file frame), its features and surface, and the
// feature options the crop pass voxelizes with.
struct ObjectForPasses {
  const Mesh& mesh;
  const FeatureGrid& features;
  const SurfaceScene& scene;
  const FeatureOptions& featureOptions;
  // The mesh's parts (connectedAndMaterialParts, z-up mesh frame) where they were found already
  // (the category decision read them); null: found here when the learned decision needs them.
  const std::vector<ConnectedPart>* meshParts = nullptr;
};

struct CategoryPoints {
  std::vector<ModelPrediction> predictions;  // one per model, in the models' order
  // Per model, its point candidates (PassOptions::keepCandidates; else empty).
  std::vector<std::vector<PointCandidate>> candidates;
  // The category's evidence (category_evidence.h): the best point confidence of the count, before
  // a learned decision chooses; the evidence gate was fitted on it.
  double evidence = 0;
};

class ModelSet;
struct Normalization;

// The mesh's parts (z-up mesh frame: connectedAndMaterialParts, crease patches) in the normalized
// frame of `normalization`: the parts the point candidates are seeded from.
std::vector<ConnectedPart> normalizedParts(std::vector<ConnectedPart> meshParts,
                                           const Normalization& normalization);

// `passes` with `models`' learned point decision (ModelSet::pointScorer) when
// passes.learnedDecision is on, and the passes it learned without (the crop) switched off; without
// it, or off, no scorer and the passes as given.
PassOptions withLearnedDecision(PassOptions passes, const ModelSet& models);

// Runs `models` (one category's) on `object`. `mode` is the instance mode; a type in `counts`
// takes InstanceMode::Count with its count (k-means), and Count without one falls back to Auto.
// The learned decision chooses only where every model is Auto. `beforeModel(i)` is called before
// model i runs (progress, cancellation), when given.
CategoryPoints predictCategoryPoints(const std::vector<const model::AffordanceModel*>& models,
                                     const ObjectForPasses& object,
                                     const PassOptions& passes, InstanceMode mode,
                                     const std::map<std::string, int>& counts = {},
                                     const std::function<void(std::size_t)>& beforeModel = {});

}  // namespace sagrid
