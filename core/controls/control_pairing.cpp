#include "core/controls/control_pairing.h"

#include <algorithm>
#include <numeric>

namespace sagrid {

namespace {

// Burners whose x differ by less than this share of the layout's width stand in one column.
constexpr float kColumnShare = 0.2f;

std::vector<std::size_t> burnerReadingOrder(const std::vector<Eigen::Vector2f>& burners) {
  std::vector<std::size_t> order(burners.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return burners[a].x() < burners[b].x(); });
  if (burners.empty()) return order;
  const float width = burners[order.back()].x() - burners[order.front()].x();
  // Columns: runs of burners sorted by x without a gap wider than the column tolerance.
  std::vector<int> column(burners.size(), 0);
  for (std::size_t i = 1; i < order.size(); ++i) {
    const bool gap = burners[order[i]].x() - burners[order[i - 1]].x() > kColumnShare * width;
    column[order[i]] = column[order[i - 1]] + (gap ? 1 : 0);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (column[a] != column[b]) return column[a] < column[b];
    return burners[a].y() < burners[b].y();  // front (-y) first
  });
  return order;
}

}  // namespace

std::vector<int> pairKnobsWithBurners(const std::vector<Eigen::Vector2f>& knobs,
                                      const std::vector<Eigen::Vector2f>& burners) {
  std::vector<std::size_t> knobOrder(knobs.size());
  std::iota(knobOrder.begin(), knobOrder.end(), std::size_t{0});
  std::stable_sort(knobOrder.begin(), knobOrder.end(),
                   [&](std::size_t a, std::size_t b) { return knobs[a].x() < knobs[b].x(); });
  const std::vector<std::size_t> burnerOrder = burnerReadingOrder(burners);
  std::vector<int> drives(knobs.size(), -1);
  for (std::size_t i = 0; i < knobOrder.size() && i < burnerOrder.size(); ++i)
    drives[knobOrder[i]] = static_cast<int>(burnerOrder[i]);
  return drives;
}

std::vector<int> pairToggleButtonsWithHeatSources(const std::vector<AffordancePoint>& points,
                                                  UpAxis fileUp) {
  std::vector<Eigen::Vector2f> knobs, burners;
  for (const AffordancePoint& p : points) {
    const Eigen::Vector2f xy = fileToZUp(p.position, fileUp).head<2>();
    if (p.type == "togglebutton") knobs.push_back(xy);
    if (p.type == "heatsource") burners.push_back(xy);
  }
  return burners.empty() ? std::vector<int>{} : pairKnobsWithBurners(knobs, burners);
}

}  // namespace sagrid
