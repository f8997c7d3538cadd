// The learning curve of the point decision left out by source (`sagrid scorer cv --ks ...`) as a
// picture: at each number k of curated objects of the other sources in training, the curator's
// edits per hand point and the first point's error, each as a share of its value with generated
// objects only, so that both read against the target (0.7 of none with all).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/eval/point_scorer_training.h"

namespace sagrid {

// The target share of the k = 0 figures with every curated object (issue 40).
inline constexpr double kLearningCurveTarget = 0.7;

struct ScorerCurveSeries {
  std::string name;
  std::vector<double> k, share;  // share of the generated-only figure, per k
};

// Edits per hand point and the first point's error over every fold ("edits", "error"), then over
// the folds of the sources no pass was made on ("edits, unseen", "error, unseen"; with tunedOn),
// each at cv.ks and, last, with all the other sources' objects (k = their mean number over the
// folds). Empty without ks; a figure that is not finite at k or at generated-only is
// left out.
std::vector<ScorerCurveSeries> scorerCurveSeries(const ScorerCrossValidation& cv);

// scorerCurveSeries as a PNG line plot with the target line; nothing without ks. Throws FileError
// when the file cannot be written.
void writeScorerLearningCurvePng(const ScorerCrossValidation& cv,
                                 const std::filesystem::path& file);

}  // namespace sagrid
