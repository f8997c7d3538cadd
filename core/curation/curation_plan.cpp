#include "core/curation/curation_plan.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/annotate/category_classifier.h"
#include "core/annotate/suggested_points.h"
#include "core/eval/hungarian.h"

namespace sagrid {

const std::vector<std::string>& categoriesWithKeys() {
  static const std::vector<std::string> categories = {"stove", "sink", kRejectedCategory};
  return categories;
}

bool isCategorySwitch(CurationAction action) {
  return action == CurationAction::Category || action == CurationAction::CategoryKey;
}

std::vector<CurationStep> curationPlan(const ObjectLabels& opened, const ObjectLabels& truth,
                                       double radiusMeters) {
  std::vector<CurationStep> steps;
  std::vector<AffordancePoint> points = opened.affordances;
  const std::optional<std::string> suggested = suggestedCategory(opened);
  if (suggested && *suggested == truth.object.category) {
    // One key (C) takes the suggested category with its points.
    CurationStep s;
    s.action = CurationAction::ConfirmCategory;
    s.category = *suggested;
    steps.push_back(s);
  } else {
    // Accepting "none" drops the suggestions; a switch to another category drops them too.
    points.erase(std::remove_if(points.begin(), points.end(), isSuggestion), points.end());
  }
  if (opened.object.category != truth.object.category && !(suggested && *suggested == truth.object.category)) {
    CurationStep s;
    const auto& keyed = categoriesWithKeys();
    const bool hasKey = std::find(keyed.begin(), keyed.end(), truth.object.category) != keyed.end();
    s.action = hasKey ? CurationAction::CategoryKey : CurationAction::Category;
    s.category = truth.object.category;
    steps.push_back(s);
    // The GUI drops points that are all still predicted when the category switches.
    const bool allPredicted = std::all_of(points.begin(), points.end(), [](const AffordancePoint& p) {
      return p.status == AffordanceStatus::Predicted;
    });
    if (allPredicted) points.clear();
  }
  const double scale = metersPerUnit(truth);
  if (std::abs(metersPerUnit(opened) / scale - 1.0) > kUnitsTolerance) {
    CurationStep s;
    s.action = CurationAction::Units;
    s.metersPerUnit = scale;
    steps.push_back(s);
  }
  std::set<std::string> types;
  for (const auto& p : points) types.insert(p.type);
  for (const auto& p : truth.affordances) types.insert(p.type);
  std::vector<std::pair<int, CurationAction>> deletions;  // index, Delete or DeleteRest
  std::vector<AffordancePoint> missing;
  for (const std::string& type : types) {
    std::vector<int> extra;
    std::vector<int> have;
    std::vector<const AffordancePoint*> want;
    for (int i = 0; i < static_cast<int>(points.size()); ++i)
      if (points[std::size_t(i)].type == type) have.push_back(i);
    for (const auto& p : truth.affordances)
      if (p.type == type) want.push_back(&p);
    std::vector<bool> wanted(want.size(), false);
    if (!have.empty() && !want.empty()) {
      std::vector<std::vector<double>> cost(have.size(), std::vector<double>(want.size()));
      for (std::size_t r = 0; r < have.size(); ++r)
        for (std::size_t c = 0; c < want.size(); ++c)
          cost[r][c] = (points[std::size_t(have[r])].position - want[c]->position).cast<double>().norm() * scale;
      const std::vector<int> match = hungarianAssignment(cost);
      for (std::size_t r = 0; r < have.size(); ++r) {
        if (match[r] < 0) {
          extra.push_back(have[r]);
          continue;
        }
        wanted[std::size_t(match[r])] = true;
        if (cost[r][std::size_t(match[r])] > radiusMeters) {
          CurationStep s;
          s.action = CurationAction::Drag;
          s.index = have[r];
          s.point = *want[std::size_t(match[r])];
          steps.push_back(s);
        }
      }
    } else {
      extra.insert(extra.end(), have.begin(), have.end());
    }
    for (std::size_t c = 0; c < want.size(); ++c)
      if (!wanted[c]) missing.push_back(*want[c]);
    // The type's last points all extra (the ranking's tail, most probable first: a count that took
    // too many) go with one key from the first of them; the others one by one.
    std::size_t tail = 0;
    while (tail < have.size() &&
           std::count(extra.begin(), extra.end(), have[have.size() - 1 - tail]) > 0)
      ++tail;
    for (int i : extra)
      if (tail < 2 || i < have[have.size() - tail]) deletions.push_back({i, CurationAction::Delete});
    if (tail >= 2) deletions.push_back({have[have.size() - tail], CurationAction::DeleteRest});
  }
  // From the back, so earlier indices stay valid (a tail's later points go with its first).
  std::sort(deletions.rbegin(), deletions.rend());
  for (const auto& [index, action] : deletions) {
    CurationStep s;
    s.action = action;
    s.index = index;
    steps.push_back(s);
  }
  for (const auto& p : missing) {
    CurationStep s;
    s.action = CurationAction::Add;
    s.point = p;
    steps.push_back(s);
  }
  return steps;
}

}  // namespace sagrid
