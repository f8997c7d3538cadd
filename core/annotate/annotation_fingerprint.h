// What a predicted labels.json was made from, so that a rerun of a batch skips an object whose
// labels are already what it would write: the mesh file's sha256, the sha256 of every model's
// weights and of the models folder's category classifier and confidence map, and a hash of the
// options that change a prediction. Stored in the labels' "prediction" block ("mesh_sha256",
// "models", "options_hash").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/annotate/annotate.h"
#include "core/labels/labels.h"

namespace sagrid {

struct AnnotationFingerprint {
  std::string meshSha256;
  nlohmann::json models = nlohmann::json::object();  // model name or file -> sha256
  std::string optionsHash;
  nlohmann::json declared;  // declaredByProvenance(mesh): null when nothing is declared
};

// What a provenance.json beside the mesh declares that annotate takes instead of guessing:
// {"up": ..., "meters_per_unit": ...} with the fields it declares; null when none.
nlohmann::json declaredByProvenance(const std::filesystem::path& mesh);

// {"<model name>": weights sha256, ..., "category.json": sha256, "confidence.json": sha256} (the
// two files only when the folder has them).
nlohmann::json modelShas(const ModelSet& models, const std::filesystem::path& modelsDir);

// Hash of the options that change a prediction: category, instance mode and counts, symmetries,
// the feature configuration and the up-axis override (not the cache folder or progress hooks).
std::string annotateOptionsHash(const AnnotateOptions& options);

// Adds the fingerprint to labels.extra["prediction"], keeping what is there.
void recordFingerprint(ObjectLabels& labels, const AnnotationFingerprint& fingerprint);

// A person has worked on the labels: a point accepted, edited or added, or the review done.
// Such labels are never overwritten by a batch without --force.
bool isCurated(const ObjectLabels& labels);

// The labels were predicted from exactly this mesh, these models and these options.
bool matchesFingerprint(const ObjectLabels& labels, const AnnotationFingerprint& fingerprint);

}  // namespace sagrid
