#include "ui/app/label_layout.h"

#include <algorithm>
#include <numeric>

namespace sagrid::ui {

namespace {

struct Box {
  Eigen::Vector2f min, max;
  bool overlaps(const Box& other, float padding) const {
    return min.x() < other.max.x() + padding && other.min.x() < max.x() + padding &&
           min.y() < other.max.y() + padding && other.min.y() < max.y() + padding;
  }
};

// Spots around the marker for a label of `size`: right, left, above right, below right.
std::vector<Eigen::Vector2f> spots(const Eigen::Vector2f& anchor, const Eigen::Vector2f& size, float gap) {
  const float x = anchor.x(), y = anchor.y(), w = size.x(), h = size.y();
  return {{x + gap, y - h / 2}, {x - gap - w, y - h / 2}, {x + gap, y - h / 2 - h - 2},
          {x + gap, y + h / 2 + 2}};
}

}  // namespace

std::vector<PlacedLabel> layOutLabels(const std::vector<LabelRequest>& requests, float gap) {
  constexpr float kPadding = 2.0f;
  std::vector<std::size_t> order(requests.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return requests[a].priority < requests[b].priority;
  });
  std::vector<PlacedLabel> placed(requests.size());
  std::vector<Box> taken;
  for (std::size_t i : order) {
    const LabelRequest& r = requests[i];
    bool found = false;
    for (bool shortened : {false, true}) {
      const Eigen::Vector2f size = shortened ? r.shortSize : r.fullSize;
      for (const Eigen::Vector2f& at : spots(r.anchor, size, gap)) {
        const Box box{at, at + size};
        if (std::any_of(taken.begin(), taken.end(),
                        [&](const Box& other) { return box.overlaps(other, kPadding); }))
          continue;
        placed[i] = {at, shortened};
        taken.push_back(box);
        found = true;
        break;
      }
      if (found) break;
    }
    if (!found) {
      const Eigen::Vector2f at = spots(r.anchor, r.shortSize, gap).front();
      placed[i] = {at, true};
      taken.push_back({at, at + r.shortSize});
    }
  }
  return placed;
}

}  // namespace sagrid::ui
