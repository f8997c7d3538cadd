#include "core/eval/count_fitting.h"

#include <cstdio>
#include <sstream>

#include "core/common/error.h"
#include "core/model/model_card.h"

namespace sagrid {

namespace fs = std::filesystem;

double rightCountShare(const FieldsWithTruth& data, const ExtractionSettings& settings) {
  if (data.fields.empty()) return 0;
  std::size_t right = 0;
  for (std::size_t o = 0; o < data.fields.size(); ++o)
    right += autoCountPoints(data.fields[o], settings).size() == data.truths[o].size();
  return static_cast<double>(right) / static_cast<double>(data.fields.size());
}

std::vector<CountFit> fitCounts(const ModelSet& models, const EvaluationReport& report) {
  std::vector<CountFit> fits;
  for (const auto& model : models.models()) {
    const auto& card = model.card();
    const auto kept = report.fieldsByModel.find(card.name);
    if (kept == report.fieldsByModel.end() || kept->second.fields.empty()) continue;
    CountFit fit;
    fit.model = card.name;
    fit.objects = kept->second.fields.size();
    fit.before = card.extraction;
    fit.after = calibrateExtraction(kept->second.fields, kept->second.truths, card.extraction);
    fit.rightBefore = rightCountShare(kept->second, fit.before);
    fit.rightAfter = rightCountShare(kept->second, fit.after);
    fits.push_back(fit);
  }
  return fits;
}

void writeModelsWithFittedCounts(const fs::path& modelsDir, const std::vector<CountFit>& fits,
                                 const fs::path& outDir) {
  std::error_code same;
  if (fs::exists(outDir) && fs::equivalent(modelsDir, outDir, same))
    throw FileError(outDir, "--fit-counts writes a new models folder, not the one evaluated "
                            "(copy the cards over deliberately)");
  fs::create_directories(outDir);
  for (const auto& entry : fs::directory_iterator(modelsDir))
    if (entry.is_regular_file())
      fs::copy_file(entry.path(), outDir / entry.path().filename(),
                    fs::copy_options::overwrite_existing);
  for (const auto& fit : fits) {
    const fs::path cardFile = outDir / (fit.model + ".json");
    model::ModelCard card = model::readModelCard(cardFile);
    card.extraction = fit.after;
    model::writeModelCard(cardFile, card);
  }
}

std::string countFitMarkdown(const std::vector<CountFit>& fits) {
  std::ostringstream out;
  out << "| Model | Objects | Max distance | NMS radius | Right count before | Right count after |\n"
         "|---|---|---|---|---|---|\n";
  char line[256];
  for (const auto& f : fits) {
    std::snprintf(line, sizeof line,
                  "| %s | %zu | %.3f -> %.3f | %.3f -> %.3f | %.1f %% | %.1f %% |\n",
                  f.model.c_str(), f.objects, f.before.maxDistance, f.after.maxDistance,
                  f.before.nmsRadius, f.after.nmsRadius, 100 * f.rightBefore, 100 * f.rightAfter);
    out << line;
  }
  return out.str();
}

}  // namespace sagrid
