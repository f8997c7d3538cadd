// No hard category gate (issue 40): an object the category decision rejects ("none") still
// carries the points of its likeliest category, flagged as suggestions: each point's
// "suggestion": true, and object.suggested_category. A curator confirms the category with one key
// (the points become ordinary predictions to review) or accepts "none" (the suggestions go), instead
// of placing every point of a rejected stove by hand.
#pragma once

#include <optional>
#include <string>

#include "core/labels/labels.h"

namespace sagrid {

inline constexpr const char* kSuggestionField = "suggestion";
inline constexpr const char* kSuggestedCategoryField = "suggested_category";

// Flags every point of `labels` as a suggestion for `category` and records the category.
void markSuggestions(ObjectLabels& labels, const std::string& category);

bool isSuggestion(const AffordancePoint& point);

// object.suggested_category, when the labels hold suggestions.
std::optional<std::string> suggestedCategory(const ObjectLabels& labels);

// The curator took the suggested category: it becomes the object's, its points ordinary
// predictions.
void confirmSuggestions(ObjectLabels& labels);

// The curator kept "none": the suggested points and the record go.
void dropSuggestions(ObjectLabels& labels);

}  // namespace sagrid
