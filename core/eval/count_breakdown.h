// The automatic count broken down by how generated objects were made: for each model and each
// generator setting recorded in the objects' labels (object.generator, e.g. a stove's `controls`:
// front_panel, touch, ...), the share of objects whose automatic count is right, too low or too
// high, and the curator's edits. A right-count share over 50 objects moves by 2 points with each
// object; the breakdown says which kind of object fails, so a change can be judged by
// the objects it was meant for. Only string settings with at least two values are broken down.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sagrid {

struct CountGroup {
  std::size_t objects = 0;
  std::size_t right = 0;  // automatic count equals the ground-truth count
  std::size_t fewer = 0;  // fewer points than the ground truth
  std::size_t more = 0;   // more points
  std::size_t edits = 0;  // curator point edits on this model's type, summed
  double rightPercent() const {
    return 100.0 * static_cast<double>(right) / static_cast<double>(objects);
  }
};

struct CountBreakdown {
  // model -> setting name -> setting value -> group
  std::map<std::string, std::map<std::string, std::map<std::string, CountGroup>>> groups;
  bool empty() const { return groups.empty(); }
  // The group of one model's objects with one setting's value; nullptr when there is none.
  const CountGroup* find(const std::string& model, const std::string& setting,
                         const std::string& value) const;
};

// From an evaluation's per-object records (EvaluationReport::perObject: "generator", "truth",
// "predictions"[model][`method`], "edits"). Objects without generator settings or without ground
// truth of a model's type are left out of that model's groups.
CountBreakdown countBreakdown(const nlohmann::json& perObject,
                              const std::string& method = "SAGrid auto count");

// One table per model (setting, value, objects, right count, too few, too many, edits / object);
// empty for an empty breakdown.
std::string countBreakdownMarkdown(const CountBreakdown& breakdown);
nlohmann::json countBreakdownJson(const CountBreakdown& breakdown);

// Several model sets' breakdowns of the same objects side by side: per model, setting and value
// the objects and each set's right-count share (column labels from `labels`, same order).
// Empty when every breakdown is.
std::string countBreakdownComparisonMarkdown(const std::vector<std::string>& labels,
                                             const std::vector<CountBreakdown>& breakdowns);

}  // namespace sagrid
