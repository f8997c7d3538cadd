#include "core/annotate/annotation_fingerprint.h"

#include <algorithm>

#include "core/annotate/category_classifier.h"
#include "core/annotate/object_confidence.h"
#include "core/annotate/point_scorer.h"
#include "core/annotate/size_memory.h"
#include "core/common/atomic_file.h"
#include "core/common/sha256.h"
#include "core/dataset/object_source.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {
namespace fs = std::filesystem;

nlohmann::json modelShas(const ModelSet& models, const fs::path& modelsDir) {
  nlohmann::json shas = nlohmann::json::object();
  for (const auto& [name, weights] : models.weightsByModel()) shas[name] = weights;
  for (const char* file : {kCategoryClassifierFile, kConfidenceFile, kPointScorerFile, kSizeMemoryFile}) {
    std::error_code ec;
    if (fs::is_regular_file(modelsDir / file, ec))
      shas[file] = sha256Hex(readFileBytes(modelsDir / file));
  }
  return shas;
}

std::string annotateOptionsHash(const AnnotateOptions& options) {
  const nlohmann::json config{
      {"category", options.category},
      {"mode", static_cast<int>(options.mode)},
      {"counts", options.counts},
      {"symmetries", options.symmetries},
      {"learned_decision", options.learnedDecision},
      {"suggestions", options.suggestions},
      {"read_file_name", options.readFileName},
      {"passes_version", kPointPassesVersion},
      {"coarse_to_fine",
       options.coarseToFine ? nlohmann::json(*options.coarseToFine) : nlohmann::json("card")},
      {"features", featureConfigHash(options.features)},
      {"up", options.features.up ? toString(*options.features.up) : ""}};
  return sha256Hex(config.dump()).substr(0, 16);
}

void recordFingerprint(ObjectLabels& labels, const AnnotationFingerprint& fingerprint) {
  auto& prediction = labels.extra["prediction"];
  if (!prediction.is_object()) prediction = nlohmann::json::object();
  prediction["mesh_sha256"] = fingerprint.meshSha256;
  if (fingerprint.declared.is_null())
    prediction.erase("declared");
  else
    prediction["declared"] = fingerprint.declared;
  prediction["models"] = fingerprint.models;
  prediction["options_hash"] = fingerprint.optionsHash;
}

bool isCurated(const ObjectLabels& labels) {
  return labels.reviewState == ReviewState::Done ||
         std::any_of(
             labels.affordances.begin(), labels.affordances.end(),
             [](const AffordancePoint& a) { return a.status != AffordanceStatus::Predicted; });
}

bool matchesFingerprint(const ObjectLabels& labels, const AnnotationFingerprint& fingerprint) {
  const auto p = labels.extra.find("prediction");
  if (p == labels.extra.end() || !p->is_object()) return false;
  return p->value("mesh_sha256", std::string()) == fingerprint.meshSha256 &&
         p->value("options_hash", std::string()) == fingerprint.optionsHash &&
         p->value("models", nlohmann::json()) == fingerprint.models &&
         p->value("declared", nlohmann::json()) == fingerprint.declared;
}

nlohmann::json declaredByProvenance(const std::filesystem::path& mesh) {
  nlohmann::json declared;
  if (const auto up = declaredUpAxis(mesh)) declared["up"] = toString(*up);
  if (const auto scale = declaredMetersPerUnit(mesh)) declared["meters_per_unit"] = *scale;
  return declared;
}

}  // namespace sagrid
