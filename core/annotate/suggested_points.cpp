#include "core/annotate/suggested_points.h"

#include <algorithm>

namespace sagrid {

void markSuggestions(ObjectLabels& labels, const std::string& category) {
  for (auto& point : labels.affordances) point.extra[kSuggestionField] = true;
  labels.object.extra[kSuggestedCategoryField] = category;
}

bool isSuggestion(const AffordancePoint& point) {
  const auto it = point.extra.find(kSuggestionField);
  return it != point.extra.end() && it->is_boolean() && it->get<bool>();
}

std::optional<std::string> suggestedCategory(const ObjectLabels& labels) {
  const auto it = labels.object.extra.find(kSuggestedCategoryField);
  if (it == labels.object.extra.end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}

void confirmSuggestions(ObjectLabels& labels) {
  if (const auto category = suggestedCategory(labels)) labels.object.category = *category;
  for (auto& point : labels.affordances) point.extra.erase(kSuggestionField);
  labels.object.extra.erase(kSuggestedCategoryField);
}

void dropSuggestions(ObjectLabels& labels) {
  labels.affordances.erase(std::remove_if(labels.affordances.begin(), labels.affordances.end(), isSuggestion),
                           labels.affordances.end());
  labels.object.extra.erase(kSuggestedCategoryField);
}

}  // namespace sagrid
