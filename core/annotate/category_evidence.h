// Affordance evidence: the category's own models as a check on the category classifier
// (EvidenceGate in category_classifier.h). The classifier reads the object's shape as a whole and
// files a blender or a coffee maker with a jug opening on top under "sink"; the sink models then
// find no tap and no handle on it. An object's evidence for a category is the confidence of the
// best point that category's models place on it (annotate with the category given: the count's
// points, before a learned decision chooses); the gate's threshold for a category is fitted on
// objects of that category so that a chosen share of them keeps it.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/annotate/annotate.h"

namespace sagrid {

// The best point confidence among `predictions` (0 when they have no points).
double affordanceEvidence(const std::vector<ModelPrediction>& predictions);

// The evidence of `category` on a mesh: annotateMeshFile with that category given and `options`
// otherwise (its up axis, feature cache, passes): AnnotationResult::evidence, the count's best
// point before a learned decision chooses. Throws as annotateMeshFile does.
double affordanceEvidence(const std::filesystem::path& meshFile, const std::string& category,
                          const ModelSet& models, AnnotateOptions options);

// `decision` after `gate`: an accepted category with a threshold, decided with a probability
// below the gate's sureProbability, is rejected (its best category kept) when evidenceOf(category),
// asked only then, falls short of it.
CategoryDecision applyEvidenceGate(const CategoryDecision& decision, const EvidenceGate& gate,
                                   const std::function<double(const std::string&)>& evidenceOf);

// The largest threshold that at least `keep` of `evidence` reach (values >= threshold). Throws
// InvalidArgument when `evidence` is empty or `keep` is not in (0, 1].
double evidenceThresholdKeeping(std::vector<double> evidence, double keep);

// A gate with, for each category of `evidenceByCategory` (evidence of objects of that category),
// the threshold that keeps `keep` of them, and the weights' sha256 of the category's models in
// `models`. Throws InvalidArgument for a category without models or without objects.
EvidenceGate fitEvidenceGate(const std::map<std::string, std::vector<double>>& evidenceByCategory,
                             double keep, const ModelSet& models);

}  // namespace sagrid
