// What a curator who knows an object's right labels does to it in the GUI, step by step, when it
// opens with predictions: take a rejected object's suggested category with one key when it is
// right (its suggested points stay), else switch the category if it is wrong, by its key where it
// has one (categoriesWithKeys), else from the list (the GUI then drops
// the old category's predicted points; accepting "none" drops suggestions), set the units if they are wrong, drag every predicted point that
// is matched (Hungarian, per type) to a right point but lies farther than the match radius, delete
// every extra point (where a type's last two or more points are all extra, with one key from the
// first of them: DeleteRest), add every missing one, and accept the rest with one key. The points
// edited are the ones core/eval/curator_effort.h counts (a DeleteRest step deletes several); the replay (ui/app/curation_replay.h) performs them
// through the GUI's own session so the curation log measures them.
#pragma once

#include <string>
#include <vector>

#include "core/curation/curation_log.h"
#include "core/eval/metrics.h"
#include "core/labels/labels.h"

namespace sagrid {

struct CurationStep {
  CurationAction action = CurationAction::Drag;  // (Confirm)Category, Units, Drag, Delete(Rest), Add
  std::string category;                          // (Confirm)Category(Key)
  double metersPerUnit = 1.0;                    // Units
  int index = -1;  // Drag, Delete, DeleteRest: the point's index at that moment
  AffordancePoint point;                         // Drag: where to; Add: the point
};

// The categories the GUI switches to with a key of their own, in key order (Shift+1, Shift+2,
// Shift+3): the category classifier's classes. Any other is picked from the Object panel's list.
const std::vector<std::string>& categoriesWithKeys();

// A step that switches the object's category: from the list (Category) or by its key (CategoryKey).
bool isCategorySwitch(CurationAction action);

// Units count as wrong when they differ by more than this ratio (0.1 %).
inline constexpr double kUnitsTolerance = 1e-3;

std::vector<CurationStep> curationPlan(const ObjectLabels& opened, const ObjectLabels& truth,
                                       double radiusMeters = kMatchRadiusMeters);

}  // namespace sagrid
