// Where the viewport's point labels go, so that the labels of a row of knobs do not pile on each
// other (a curator's complaint: "1 togglebutton ?" over "2 togglebutton ?" over ...). Every
// label first takes the first free spot around its marker (right, left, above, below) as its
// number alone, so a dense row keeps all its numbers; then, in the same order, a label grows to its
// full text at the first spot where the full text overlaps no other label. Labels go in priority
// order (the selected point, then points the eye sees, then hidden ones). A number with no free
// spot sits on the right, overlapping.
#pragma once

#include <Eigen/Core>
#include <cstddef>
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

// Lays out the viewport's labels every frame; keeps its buffers from one frame to the next.
class LabelLayout {
 public:
  // One placement per request, in the requests' order. `gap`: pixels between marker and label.
  const std::vector<PlacedLabel>& place(const std::vector<LabelRequest>& requests, float gap);

 private:
  struct Box {
    Eigen::Vector2f min, max;
  };
  std::vector<std::size_t> m_order;
  std::vector<PlacedLabel> m_placed;
  std::vector<Box> m_taken;  // each request's label box once placed (m_placedYet)
  std::vector<char> m_placedYet;
};

}  // namespace sagrid::ui
