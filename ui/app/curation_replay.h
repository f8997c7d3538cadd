// A curator who knows the right labels, replayed through the GUI's own session (issue 41): each
// object of the session's queue is opened, the steps of core/curation/curation_plan.h are taken
// with the same calls the GUI's keys and panels make (category list, units list, point drag,
// Del, add, R where a row of equal parts holds the points to add, E after an addition while the
// row's next point is one to add), and the object is accepted with A. The session's curation
// log then records exactly the actions a person would need, so `sagrid eval --curation` measures
// the GUI's throughput on real objects from the models' predictions, the same whoever runs it.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/labels/labels.h"

namespace sagrid::ui {

class Session;

struct CurationReplaySummary {
  std::size_t objects = 0;       // replayed and accepted
  std::size_t withoutTruth = 0;  // skipped (S): no right labels for them
  std::size_t failed = 0;        // could not be opened
};

// With `repredict` and a predictor on the session, a category switch predicts again for the new
// category, as in the GUI, and the rest of the plan starts from those points; objects never
// predict on opening (their labels.json hold the predictions to start from).
// `truthOf(id)` returns the right labels of an object, named by its mesh's folder (an object
// folder, as datasets lay them out), or nullopt to skip it.
CurationReplaySummary replayCuration(Session& session,
                                     const std::function<std::optional<ObjectLabels>(const std::string&)>& truthOf,
                                     bool repredict = true);

}  // namespace sagrid::ui
