// Two or more model sets evaluated on the same objects, side by side in one table (e.g. the
// shipped models against a fine-tuned set): the paper's single-point error per type and its
// average, recall and right count of the automatic count, and the curator's effort.
#pragma once

#include <string>
#include <vector>

#include "core/eval/evaluation.h"

namespace sagrid {

struct LabelledReport {
  std::string label;  // e.g. the model folder
  const EvaluationReport* report = nullptr;
};

// Markdown; throws InvalidArgument when the reports cover different object counts (then they
// were not run on the same data and a side-by-side table would mislead).
std::string comparisonMarkdown(const std::vector<LabelledReport>& reports);
nlohmann::json comparisonJson(const std::vector<LabelledReport>& reports);

}  // namespace sagrid
