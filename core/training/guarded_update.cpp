#include "core/training/guarded_update.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/annotate/model_set.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/report_cell.h"
#include "core/dataset/dataset.h"
#include "core/eval/evaluation.h"
#include "core/labels/labels.h"
#include "core/model/model_card.h"
#include "core/model/model_files.h"
#include "core/training/curated_data_check.h"

namespace sagrid {

namespace fs = std::filesystem;

namespace {

// Held-out objects of the model's category with points of its type.
std::size_t heldOutObjectsOfType(const GuardOptions& o) {
  const auto [category, type] = model::splitModelName(o.modelName);
  std::size_t count = 0;
  for (const auto& entry : readDataset(o.heldOutDir, o.referenceRoot)) {
    const ObjectLabels labels = readLabels(entry.labels);
    const std::string objectCategory = entry.category.empty() ? labels.object.category : entry.category;
    if (objectCategory == category && !labels.ofType(type).empty()) ++count;
  }
  return count;
}

}  // namespace

// The model is loaded alone from a folder of its own (a copy of its files).
HeldOutError heldOutError(const fs::path& modelsDir, const GuardOptions& o) {
  const fs::path scratch = o.candidateDir / ".guard-scratch";
  fs::remove_all(scratch);
  model::copyModelFiles(modelsDir, scratch, o.modelName);
  const ModelSet models = ModelSet::load(scratch);
  EvaluationOptions e;
  e.dataDir = o.heldOutDir;
  e.referenceRoot = o.referenceRoot;
  e.features = o.features ? *o.features : models.featureOptions();
  e.features.cacheDir = o.cacheDir.empty() ? o.heldOutDir / ".sagrid-cache" : o.cacheDir;
  const EvaluationReport report = evaluateModels(models, e);
  fs::remove_all(scratch);
  HeldOutError out{NAN, 0, {}};
  const auto& byModel = report.methods.front().byModel;  // "SAGrid argmin (paper)"
  if (const auto it = byModel.find(o.modelName); it != byModel.end() && it->second.objects > 0) {
    out.objects = it->second.objects;
    out.error = it->second.paperError;
  }
  for (const auto& object : report.perObject)
    if (object.contains("paper_error_m") && object["paper_error_m"].contains(o.modelName))
      out.byObject[object.at("id").get<std::string>()] =
          object["paper_error_m"][o.modelName].get<double>();
  return out;
}

void checkGuardedUpdate(const GuardOptions& o, const std::vector<fs::path>& trainingDirs) {
  try {
    ModelSet::load(o.currentDir);
  } catch (const ModelError& e) {
    throw ModelError(o.currentDir.string() + " does not load as one set of models (" + e.what() +
                     "); nothing was trained and the current models stay: keep models of one "
                     "version and feature setup in a folder");
  }
  requireSoundCuratedData({trainingDirs, o.heldOutDir, o.referenceRoot});
}

GuardVerdict judgeUpdate(const GuardOptions& o, const std::optional<HeldOutError>& known) {
  if (heldOutObjectsOfType(o) == 0) {
    GuardVerdict v;
    v.model = o.modelName;
    v.currentError = v.candidateError = NAN;
    v.reason = "no held-out object of its type in " + o.heldOutDir.string() + ": current model kept";
    return v;
  }
  const HeldOutError current = known ? *known : heldOutError(o.currentDir, o);
  const HeldOutError candidate = heldOutError(o.candidateDir, o);
  GuardVerdict v;
  v.model = o.modelName;
  v.currentError = current.error;
  v.candidateError = candidate.error;
  if (candidate.objects == 0) {
    v.reason = "no held-out object of its type in " + o.heldOutDir.string() + ": current model kept";
    return v;
  }
  decideOnPairedErrors(v, pairById(current.byObject, candidate.byObject),
                       std::to_string(candidate.objects) + " held-out object(s)");
  return v;
}

void decideOnPairedErrors(GuardVerdict& v, const std::vector<ObjectFigures>& errors,
                          const std::string& where) {
  const PairedChange change = pairedChange(errors);
  v.objects = change.objects;
  v.currentError = change.current;
  v.candidateError = change.candidate;
  v.pairedNoise = change.noise;
  v.adopted = change.clearlyBetter();
  if (errors.empty()) {
    v.reason = "no object judged by both models on " + where + ": current model kept";
    return;
  }
  v.reason = reportCell(v.currentError * 100, "%.1f cm") + " -> " +
             reportCell(v.candidateError * 100, "%.1f cm") + " (noise " +
             reportCell(v.pairedNoise * 100, "%.1f cm") + ") on " + where + ": " +
             (v.adopted ? "adopted" : change.verdict() + ", current model kept");
}

void applyVerdict(const GuardVerdict& v, const GuardOptions& o, const fs::path& outDir) {
  const auto number = [](double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
  };
  fs::create_directories(outDir);
  if (v.adopted) {
    model::moveModelFiles(o.candidateDir, outDir, o.modelName);
  } else {
    if (fs::is_directory(o.candidateDir))
      model::moveModelFiles(o.candidateDir, outDir / "refused", o.modelName);
    if (fs::weakly_canonical(o.currentDir) != fs::weakly_canonical(outDir))
      model::copyModelFiles(o.currentDir, outDir, o.modelName);
  }
  nlohmann::json line = {{"model", v.model}, {"objects", v.objects}};
  if (v.judgedBySource) {
    line["judged_by_source"] = true;
    line["sources"] = v.sources;
    line["folds"] = v.folds;
  } else {
    line["held_out"] = fs::absolute(o.heldOutDir).lexically_normal().string();
  }
  line["paired_noise_m"] = number(v.pairedNoise);
  line["current_error_m"] = number(v.currentError);
  line["candidate_error_m"] = number(v.candidateError);
  line["adopted"] = v.adopted;
  line["time"] = currentUtcTimestamp();
  std::ofstream(outDir / "guard.jsonl", std::ios::app) << line.dump() << "\n";
}

}  // namespace sagrid
