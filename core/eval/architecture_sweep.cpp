#include "core/eval/architecture_sweep.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/eval/evaluation.h"
#include "core/model/architecture.h"
#include "core/training/dataset_training.h"

namespace sagrid {
namespace fs = std::filesystem;

std::vector<std::string> splitArchitectures(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ';')) {
    if (part.find_first_not_of(" \t") == std::string::npos) continue;
    out.push_back(model::Architecture::parse(part).toString());  // validates early
  }
  if (out.empty()) throw InvalidArgument("--sweep: no architectures given");
  return out;
}

SweepResult runArchitectureSweep(const SweepOptions& o) {
  if (!fs::is_directory(o.dataDir / "train") || !fs::is_directory(o.dataDir / "val"))
    throw FileError(
        o.dataDir,
        "an architecture sweep needs train/ and val/ splits (sagrid generate --preset bench)");
  const std::vector<std::string> names = o.modelNames.empty() ? defaultModelNames() : o.modelNames;
  const fs::path cache = o.cacheDir.empty() ? o.dataDir / ".sagrid-cache" : o.cacheDir;
  SweepResult result;
  for (std::size_t a = 0; a < o.architectures.size(); ++a) {
    SweepRow row;
    row.id = "A" + std::to_string(a + 1);
    row.architecture = o.architectures[a];
    const fs::path dir = o.outDir / "sweep" / ("arch" + std::to_string(a + 1));
    for (const auto& name : names) {
      DatasetTrainingOptions t;
      t.dataDir = o.dataDir / "train";
      t.modelName = name;
      t.architecture = row.architecture;
      t.mode = o.mode;
      t.outDir = dir;
      t.features.cacheDir = cache;
      t.training.epochs = o.epochs;
      t.training.minutes = o.epochs > 0 ? 0 : o.minutes;
      t.training.nearWeight = o.nearWeight;
      t.command = "sagrid eval --sweep (architecture " + row.id + ")";
      const auto trained = trainFromDataset(t);
      row.trainSeconds += trained.trainingSeconds;
    }
    const ModelSet models = ModelSet::load(dir);
    EvaluationOptions e;
    e.dataDir = o.dataDir / "val";
    e.features = models.featureOptions();
    e.features.cacheDir = cache;
    e.onProgress = o.onProgress;
    const EvaluationReport report = evaluateModels(models, e);
    writeEvaluationReport(report, dir);
    result.meanOccupiedVoxels = report.meanOccupiedVoxels;
    double sum = 0;
    int count = 0;
    for (const auto& m : report.methods.front().byModel) {  // SAGrid argmin (paper metric)
      row.errorByModel[m.first] = m.second.paperError;
      sum += m.second.paperError;
      ++count;
    }
    row.meanError = count ? sum / count : 0;
    row.modelMilliseconds = report.modelMilliseconds;
    const auto& first = models.models().front();
    row.forwardGmac = first.forwardMacs(static_cast<std::int64_t>(report.meanOccupiedVoxels)) / 1e9;
    row.denseGmac = first.forwardMacs(0, true) / 1e9;
    row.parameters = first.parameterCount();
    result.rows.push_back(row);
  }
  std::stable_sort(result.rows.begin(), result.rows.end(),
                   [](const SweepRow& a, const SweepRow& b) { return a.meanError < b.meanError; });
  fs::create_directories(o.outDir);
  writeFileAtomic(o.outDir / "sweep.md", sweepMarkdown(result));
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : result.rows)
    j.push_back({{"id", r.id},
                 {"architecture", r.architecture},
                 {"error_m", r.meanError},
                 {"error_by_model_m", r.errorByModel},
                 {"train_seconds", r.trainSeconds},
                 {"forward_gmac", r.forwardGmac},
                 {"dense_gmac", r.denseGmac},
                 {"model_ms_per_object", r.modelMilliseconds},
                 {"parameters", r.parameters}});
  writeFileAtomic(o.outDir / "sweep.json", j.dump(2) + "\n");
  return result;
}

std::string sweepMarkdown(const SweepResult& r) {
  std::ostringstream md;
  char line[512];
  md << "| Model ID | CNN Architecture | Error (cm) | Train (s, all models) | GMAC/forward "
        "(sparse, "
     << static_cast<long>(r.meanOccupiedVoxels)
     << " voxels) | GMAC dense 64^3 | ms/object | Parameters |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : r.rows) {
    std::snprintf(line, sizeof line, "| %s | %s | %.2f | %.0f | %.2f | %.1f | %.0f | %lld |\n",
                  row.id.c_str(), row.architecture.c_str(), 100 * row.meanError, row.trainSeconds,
                  row.forwardGmac, row.denseGmac, row.modelMilliseconds,
                  static_cast<long long>(row.parameters));
    md << line;
  }
  return md.str();
}

}  // namespace sagrid
