// Where the viewport's point labels go, so that the labels of a row of knobs do not pile on each
// other (a curator's complaint: "1 togglebutton ?" over "2 togglebutton ?" over ...). Each label
// tries a few spots around its marker (right, left, above, below) in full, then as its number
// alone; the first spot free of every label placed before it wins, and labels are placed in
// priority order (the selected point, then points the eye sees, then hidden ones). A label with
// no free spot takes its number alone on the right, overlapping.
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
