#include "core/annotate/category_evidence.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"

namespace sagrid {

double affordanceEvidence(const std::vector<ModelPrediction>& predictions) {
  double best = 0;
  for (const auto& p : predictions)
    for (const auto& point : p.points) best = std::max(best, static_cast<double>(point.confidence));
  return best;
}

double affordanceEvidence(const std::filesystem::path& meshFile, const std::string& category,
                          const ModelSet& models, AnnotateOptions options) {
  options.category = category;
  return annotateMeshFile(meshFile, meshFile.stem().string(), models, options,
                          meshFile.parent_path())
      .evidence;
}

CategoryDecision applyEvidenceGate(const CategoryDecision& decision, const EvidenceGate& gate,
                                   const std::function<double(const std::string&)>& evidenceOf) {
  if (decision.rejected || !gate.thresholds.count(decision.category) || !gate.asks(decision.score))
    return decision;
  if (gate.passes(decision.category, evidenceOf(decision.category))) return decision;
  CategoryDecision rejected = decision;
  rejected.rejected = true;
  rejected.category = kRejectedCategory;
  return rejected;
}

double evidenceThresholdKeeping(std::vector<double> evidence, double keep) {
  if (evidence.empty()) throw InvalidArgument("no evidence values to fit a threshold on");
  if (!(keep > 0 && keep <= 1))
    throw InvalidArgument("the share of objects the evidence gate keeps must be in (0, 1], got " +
                          std::to_string(keep));
  std::sort(evidence.begin(), evidence.end());
  // At most this many may fall below the threshold; the next value is the threshold.
  const auto below = static_cast<std::size_t>(
      std::floor((1.0 - keep) * static_cast<double>(evidence.size()) + 1e-9));
  return evidence[std::min(below, evidence.size() - 1)];
}

EvidenceGate fitEvidenceGate(const std::map<std::string, std::vector<double>>& evidenceByCategory,
                             double keep, const ModelSet& models) {
  EvidenceGate gate;
  gate.record["keep"] = keep;
  for (const auto& [category, evidence] : evidenceByCategory) {
    // forCategory throws InvalidArgument for a category without models.
    const auto categoryModels = models.forCategory(category);
    if (evidence.empty())
      throw InvalidArgument("evidence gate: no objects of category \"" + category + "\"");
    gate.thresholds[category] = evidenceThresholdKeeping(evidence, keep);
    for (const auto* m : categoryModels)
      gate.modelShas[m->card().name] = m->card().weightsIdentity();
    gate.record["objects"][category] = evidence.size();
  }
  return gate;
}

}  // namespace sagrid
