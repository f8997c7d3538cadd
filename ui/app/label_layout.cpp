#include "ui/app/label_layout.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>

namespace sagrid::ui {

namespace {

constexpr float kPadding = 2.0f;

bool overlap(const Eigen::Vector2f& minA, const Eigen::Vector2f& maxA, const Eigen::Vector2f& minB,
             const Eigen::Vector2f& maxB) {
  return minA.x() < maxB.x() + kPadding && minB.x() < maxA.x() + kPadding &&
         minA.y() < maxB.y() + kPadding && minB.y() < maxA.y() + kPadding;
}

// Spots around the marker for a label of `size`: right, left, above right, below right.
std::array<Eigen::Vector2f, 4> spots(const Eigen::Vector2f& anchor, const Eigen::Vector2f& size,
                                     float gap) {
  const float x = anchor.x(), y = anchor.y(), w = size.x(), h = size.y();
  return {Eigen::Vector2f(x + gap, y - h / 2), Eigen::Vector2f(x - gap - w, y - h / 2),
          Eigen::Vector2f(x + gap, y - h / 2 - h - 2), Eigen::Vector2f(x + gap, y + h / 2 + 2)};
}

}  // namespace

const std::vector<PlacedLabel>& LabelLayout::place(const std::vector<LabelRequest>& requests,
                                                   float gap) {
  const std::size_t n = requests.size();
  m_order.resize(n);
  std::iota(m_order.begin(), m_order.end(), std::size_t(0));
  std::stable_sort(m_order.begin(), m_order.end(), [&](std::size_t a, std::size_t b) {
    return requests[a].priority < requests[b].priority;
  });
  m_placed.assign(n, PlacedLabel{});
  m_taken.resize(n);
  m_placedYet.assign(n, 0);
  // The first spot of `size` around request i free of every other label placed so far.
  auto freeSpot = [&](std::size_t i, const Eigen::Vector2f& size) -> std::optional<Eigen::Vector2f> {
    for (const Eigen::Vector2f& at : spots(requests[i].anchor, size, gap)) {
      bool free = true;
      for (std::size_t j = 0; j < n && free; ++j)
        free = j == i || !m_placedYet[j] || !overlap(at, at + size, m_taken[j].min, m_taken[j].max);
      if (free) return at;
    }
    return std::nullopt;
  };
  auto put = [&](std::size_t i, const Eigen::Vector2f& at, const Eigen::Vector2f& size, bool shortened) {
    m_placed[i] = {at, shortened};
    m_taken[i] = {at, at + size};
    m_placedYet[i] = 1;
  };
  // Every point gets its number first (a row of knobs keeps all its numbers), then a label grows
  // to its full text where that fits.
  for (std::size_t i : m_order) {
    const Eigen::Vector2f& size = requests[i].shortSize;
    put(i, freeSpot(i, size).value_or(spots(requests[i].anchor, size, gap).front()), size, true);
  }
  for (std::size_t i : m_order)
    if (const auto at = freeSpot(i, requests[i].fullSize)) put(i, *at, requests[i].fullSize, false);
  return m_placed;
}

}  // namespace sagrid::ui
