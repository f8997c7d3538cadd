// How well the control parts annotate finds agree with the parts a curator marked (issue 42): for
// every toggle button point whose labels.json control the curator confirmed in the GUI (kept as
// found, reshaped with the brush, Grow or Shrink, or given an axis, motion, pivot or burner;
// control_record.h), the part findControlParts
// finds at the object's toggle points (as annotate and
// the exports do, every toggle point of the object told apart) against the marked one: the
// triangle IoU by area and the angle between their axes (as lines: a knob turned either way is
// the same joint). Reported per source too, so that a rule judged on some sources is seen on the
// others. For a marked knob also how far the curator's axis lies from the knob's own axis of
// rotational symmetry: a mark picked among the view's axes for a knob on a sloped panel shows.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/dataset/dataset.h"

namespace sagrid {

struct PartAgreement {
  std::string object;
  std::string source;       // its source (a wild-pool repository, a Sweet Home 3D library, ...)
  int point = 0;            // 1-based among the object's points, as the GUI numbers them
  std::string found;        // the found part's origin, or "site" when none was found
  std::string motion;       // the curator's part's motion
  double iou = 0;           // by area; 0 when none was found
  double axisDegrees = 90;  // between the axes as lines; 90 when none was found
  // A knob's check on its mark (core/controls/control_symmetry.h): the angle between the
  // curator's axis and the marked part's own axis of rotational symmetry, and how nearly the part
  // is a body of revolution about that own axis (its misfit). Unset for levers and buttons.
  std::optional<double> markOffOwnAxisDegrees;
  std::optional<double> ownAxisMisfit;
};

struct PartAgreementReport {
  std::vector<PartAgreement> points;
  std::size_t objects = 0;  // with at least one confirmed part
  double meanIou = 0, shareIouAtLeast08 = 0, meanAxisDegrees = 0, shareAxisWithin10 = 0;
  std::vector<std::string> skipped;  // objects that could not be read, with why
};

struct PartTruth;

// Objects without confirmed parts are passed over; one that cannot be read is named in `skipped`.
// With `truth` (part_truth.h) the curator's parts are the truth's, not the labels' records: objects
// it lacks are passed over; one whose mesh changed since it was marked, one whose marked point is no
// toggle button and each of its objects not among `entries` are named in `skipped`.
PartAgreementReport measurePartAgreement(const std::vector<DatasetEntry>& entries,
                                         const PartTruth* truth = nullptr);

std::string partAgreementMarkdown(const PartAgreementReport& report);
nlohmann::json toJson(const PartAgreementReport& report);

}  // namespace sagrid
