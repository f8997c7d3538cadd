// Refits the automatic instance count of each model (ExtractionSettings' threshold, basin depth
// and nmsRadius, see calibrateExtraction) on the fields an evaluation kept — the fields annotate
// really sees (test-time symmetries, held-out objects) rather than the training fields of the
// model's own training objects, on which training calibrates. `sagrid eval --fit-counts DIR`.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/eval/evaluation.h"
#include "core/points/point_extraction.h"

namespace sagrid {

// What the refit optimises: the share of objects with the right count, or the curator's point
// edits (drags, deletions, additions with the 5 cm match radius, core/eval/curator_effort.h),
// which also weighs where the kept points lie: an extra point far from everything costs a
// deletion, a missing one an addition.
enum class CountObjective { RightCount, CuratorEdits };

struct CountFit {
  std::string model;
  std::size_t objects = 0;  // evaluated objects with the model's type
  ExtractionSettings before, after;
  double rightBefore = 0, rightAfter = 0;  // share of those objects with the right count
  double editsBefore = 0, editsAfter = 0;  // curator point edits per object of this type
};

// Share of `fields` whose automatic count with `settings` equals the ground-truth count.
double rightCountShare(const FieldsWithTruth& data, const ExtractionSettings& settings);
// Mean point edits per object of the automatic count's points with `settings` (before surface
// projection, so close to but not exactly the figure `sagrid eval` reports).
double editsPerObject(const FieldsWithTruth& data, const ExtractionSettings& settings);

// One fit per model with kept fields (EvaluationOptions::keepFields). Refinement and confidence
// scale stay the card's.
std::vector<CountFit> fitCounts(const ModelSet& models, const EvaluationReport& report,
                                CountObjective objective = CountObjective::RightCount);

// Writes a models folder: every file of `modelsDir` copied, the cards of `fits` with their
// refitted settings. Throws FileError when `outDir` is `modelsDir` (the shipped cards are only
// replaced deliberately, by copying).
void writeModelsWithFittedCounts(const std::filesystem::path& modelsDir,
                                 const std::vector<CountFit>& fits,
                                 const std::filesystem::path& outDir);

// A Markdown table: model, objects, settings and right-count share before and after.
std::string countFitMarkdown(const std::vector<CountFit>& fits);

}  // namespace sagrid
