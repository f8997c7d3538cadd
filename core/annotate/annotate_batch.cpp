#include "core/annotate/annotate_batch.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>

#include "core/annotate/annotation_fingerprint.h"
#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/common/file_lock.h"
#include "core/common/sha256.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {
// Resident memory of this process in MiB (VmRSS), 0 when unknown.
double residentMiB() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      double kib = 0;
      status >> kib;
      return kib / 1024.0;
    }
    status.ignore(1 << 12, '\n');
  }
  return 0;
}

struct LoadedModels {
  ModelSet models;
  nlohmann::json shas;
  std::string optionsHash;
};

nlohmann::json annotateOne(const MeshFile& file, const AnnotateBatchSettings& s,
                           const LoadedModels& loaded) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  nlohmann::json result{{"models", loaded.shas}};
  const auto lock = FileLock::tryAcquire(s.out / kObjectLocksFolder / (file.id + ".lock"));
  if (!lock) {
    result["status"] = batch_status::kBusy;
    return result;
  }
  const fs::path dir = s.out / file.id;
  const fs::path labelsFile = dir / "labels.json";
  AnnotationFingerprint fingerprint{sha256Hex(readFileBytes(file.path)), loaded.shas,
                                    loaded.optionsHash, declaredByProvenance(file.path)};
  std::error_code ec;
  if (!s.force && fs::exists(labelsFile, ec)) {
    ObjectLabels existing;
    try {
      existing = readLabels(labelsFile);
    } catch (const Error& e) {
      throw Error(std::string(e.what()) +
                  " (an existing labels file is never overwritten unless it is readable; fix or "
                  "remove it, or rerun with --force)");
    }
    if (isCurated(existing)) {
      result["status"] = batch_status::kCurated;
      result["category"] = existing.object.category;
      return result;
    }
    if (matchesFingerprint(existing, fingerprint)) {
      result["status"] = batch_status::kUpToDate;
      result["category"] = existing.object.category;
      result["points"] = existing.affordances.size();
      return result;
    }
  }
  AnnotationResult r = annotateMeshFile(file.path, file.id, loaded.models, s.options, dir);
  recordFingerprint(r.labels, fingerprint);
  try {
    fs::create_directories(dir);
    writeLabels(labelsFile, r.labels);
  } catch (const std::exception& e) {
    result["status"] = batch_status::kFailed;
    result["error"] = e.what();
    result["output_error"] = true;
    return result;
  }
  const auto seconds = [](double x) { return std::round(x * 1000) / 1000; };
  result["status"] = batch_status::kAnnotated;
  result["category"] = r.category;
  if (r.rejected) result["closest_category"] = r.closestCategory;
  result["points"] = r.labels.affordances.size();
  result["seconds"] = {{"import", seconds(r.importSeconds)},
                       {"features", seconds(r.featureSeconds)},
                       {"models", seconds(r.modelSeconds)},
                       {"total", seconds(secondsSince(start))}};
  result["rss_mib"] = std::round(residentMiB());
  return result;
}
}  // namespace

WorkerSetup annotateWorkerSetup(const AnnotateBatchSettings& settings) {
  return [base = settings]() -> ObjectTask {
    auto loaded = std::make_shared<LoadedModels>(
        LoadedModels{ModelSet::load(base.modelsDir), nlohmann::json(), std::string()});
    AnnotateBatchSettings settings = base;
    FeatureOptions& features = settings.options.features;
    const FeatureOptions cards = loaded->models.featureOptions();
    features.backend = cards.backend;
    features.resolution = cards.resolution;
    settings.options.confidence = readConfidenceCalibration(settings.modelsDir);
    loaded->shas = modelShas(loaded->models, settings.modelsDir);
    loaded->optionsHash = annotateOptionsHash(settings.options);
    return [settings, loaded](const MeshFile& file) -> nlohmann::json {
      try {
        return annotateOne(file, settings, *loaded);
      } catch (const std::exception& e) {
        return {{"status", batch_status::kFailed}, {"error", e.what()}, {"models", loaded->shas}};
      }
    };
  };
}

}  // namespace sagrid
