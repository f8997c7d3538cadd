// Where the viewport's point labels go, so that the labels of a row of knobs do not pile on each
// other (a curator's complaint: "1 togglebutton ?" over "2 togglebutton ?" over ...). Every
// label first takes the first free spot around its marker (right, left, above, below) as its
// number alone, so a dense row keeps all its numbers; then, in the same order, a label grows to its
// full text at the first spot where the full text overlaps no other label. Labels go in priority
// order (the selected point, then points the eye sees, then hidden ones). A number with no free
// spot sits on the right, overlapping.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sagrid::ui {

struct LabelRequest {
  Eigen::Vector2f anchor;     // the marker's centre, pixels
  Eigen::Vector2f fullSize;   // "3 togglebutton ?"
  Eigen::Vector2f shortSize;  // "3"
  int priority = 1;           // lower first
};

struct PlacedLabel {
  Eigen::Vector2f topLeft;
  bool shortened = false;
};

// One placement per request, in the requests' order. `gap`: pixels between marker and label.
std::vector<PlacedLabel> layOutLabels(const std::vector<LabelRequest>& requests, float gap);

}  // namespace sagrid::ui
