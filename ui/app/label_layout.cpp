#include "ui/app/label_layout.h"

#include <algorithm>
#include <numeric>
#include <optional>

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
  std::vector<Box> taken(requests.size());
  std::vector<bool> hasBox(requests.size(), false);
  // The first spot of `size` around request i free of every other label placed so far.
  auto freeSpot = [&](std::size_t i, const Eigen::Vector2f& size) -> std::optional<Eigen::Vector2f> {
    for (const Eigen::Vector2f& at : spots(requests[i].anchor, size, gap)) {
      const Box box{at, at + size};
      bool free = true;
      for (std::size_t j = 0; j < requests.size() && free; ++j)
        free = j == i || !hasBox[j] || !box.overlaps(taken[j], kPadding);
      if (free) return at;
    }
    return std::nullopt;
  };
  // Every point gets its number first (a row of knobs keeps all its numbers), then a label grows
  // to its full text where that fits.
  for (std::size_t i : order) {
    const Eigen::Vector2f& size = requests[i].shortSize;
    const Eigen::Vector2f at = freeSpot(i, size).value_or(spots(requests[i].anchor, size, gap).front());
    placed[i] = {at, true};
    taken[i] = {at, at + size};
    hasBox[i] = true;
  }
  for (std::size_t i : order) {
    const Eigen::Vector2f& size = requests[i].fullSize;
    if (const auto at = freeSpot(i, size)) {
      placed[i] = {*at, false};
      taken[i] = {*at, *at + size};
    }
  }
  return placed;
}

}  // namespace sagrid::ui
