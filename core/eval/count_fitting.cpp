#include "core/eval/count_fitting.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/common/error.h"
#include "core/eval/curator_effort.h"
#include "core/eval/metrics.h"
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

namespace {

std::vector<Eigen::Vector3f> positions(const std::vector<ExtractedPoint>& points) {
  std::vector<Eigen::Vector3f> out;
  for (const auto& p : points) out.push_back(p.position);
  return out;
}

std::size_t edits(const FieldsWithTruth& data, std::size_t o,
                  const std::vector<Eigen::Vector3f>& points) {
  return pointEdits(matchPoints(points, data.truths[o], data.metresPerUnit[o])).total();
}

}  // namespace

double editsPerObject(const FieldsWithTruth& data, const ExtractionSettings& settings) {
  if (data.fields.empty()) return 0;
  if (data.metresPerUnit.size() != data.fields.size()) return NAN;  // no scale: not measurable
  double sum = 0;
  for (std::size_t o = 0; o < data.fields.size(); ++o)
    sum +=
        static_cast<double>(edits(data, o, positions(autoCountPoints(data.fields[o], settings))));
  return sum / static_cast<double>(data.fields.size());
}

std::vector<CountFit> fitCounts(const ModelSet& models, const EvaluationReport& report,
                                CountObjective objective) {
  std::vector<CountFit> fits;
  for (const auto& model : models.models()) {
    const auto& card = model.card();
    const auto kept = report.fieldsByModel.find(card.name);
    if (kept == report.fieldsByModel.end() || kept->second.fields.empty()) continue;
    const FieldsWithTruth& data = kept->second;
    CountFit fit;
    fit.model = card.name;
    fit.objects = data.fields.size();
    fit.before = card.extraction;
    if (objective == CountObjective::CuratorEdits) {
      if (data.metresPerUnit.size() != data.fields.size())
        throw InvalidArgument("count fit for " + card.name +
                              ": curator edits need each object's scale (metres per unit)");
      fit.after = calibrateExtraction(
          data.fields,
          [&](std::size_t o, const std::vector<Eigen::Vector3f>& points) {
            return static_cast<double>(edits(data, o, points));
          },
          card.extraction);
    } else {
      fit.after = calibrateExtraction(data.fields, data.truths, card.extraction);
    }
    fit.rightBefore = rightCountShare(data, fit.before);
    fit.rightAfter = rightCountShare(data, fit.after);
    fit.editsBefore = editsPerObject(data, fit.before);
    fit.editsAfter = editsPerObject(data, fit.after);
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

namespace {

std::string thresholdText(const ExtractionSettings& s) {
  char text[64];
  std::snprintf(text, sizeof text, "%s%.3f", s.maxDistanceAboveBest ? "best + " : "",
                s.maxDistance);
  return text;
}

}  // namespace

std::string countFitMarkdown(const std::vector<CountFit>& fits) {
  std::ostringstream out;
  out << "| Model | Objects | Max distance | Min basin depth | NMS radius | Right count | Point "
         "edits / object |\n"
         "|---|---|---|---|---|---|---|\n";
  char line[384];
  for (const auto& f : fits) {
    std::snprintf(line, sizeof line,
                  "| %s | %zu | %s -> %s | %.3f -> %.3f | %.3f -> %.3f | %.1f %% -> %.1f %% | "
                  "%.2f -> %.2f |\n",
                  f.model.c_str(), f.objects, thresholdText(f.before).c_str(),
                  thresholdText(f.after).c_str(), f.before.minPersistence, f.after.minPersistence,
                  f.before.nmsRadius, f.after.nmsRadius, 100 * f.rightBefore, 100 * f.rightAfter,
                  f.editsBefore, f.editsAfter);
    out << line;
  }
  return out.str();
}

}  // namespace sagrid
