#include "core/geometry/part_rows.h"

#include <algorithm>
#include <cmath>

namespace sagrid {

namespace {
float offLine(const PartRow& row, const Eigen::Vector3f& p) {
  const Eigen::Vector3f d = p - row.origin;
  return (d - d.dot(row.direction) * row.direction).norm();
}
}  // namespace

std::optional<PartRow> partRow(const std::vector<std::size_t>& family,
                               const std::vector<ConnectedPart>& parts, float lineShare) {
  if (family.size() < 3) return std::nullopt;
  // The outermost two: the farthest pair of centroids.
  std::size_t a = family[0], b = family[0];
  float widest = 0;
  for (std::size_t i : family)
    for (std::size_t j : family) {
      const float d = (parts[i].centroid - parts[j].centroid).norm();
      if (d > widest) widest = d, a = i, b = j;
    }
  if (!(widest > 0)) return std::nullopt;
  PartRow row;
  row.origin = parts[a].centroid;
  row.direction = (parts[b].centroid - parts[a].centroid) / widest;
  row.first = 0, row.last = widest;
  row.spacing = widest / static_cast<float>(family.size() - 1);
  for (std::size_t p : family)
    if (offLine(row, parts[p].centroid) > lineShare * row.spacing) return std::nullopt;
  return row;
}

std::vector<std::size_t> rowContinuations(const PartRow& row,
                                          const std::vector<std::size_t>& candidates,
                                          const std::vector<ConnectedPart>& parts, float lineShare,
                                          float reachSpacings) {
  std::vector<std::size_t> out;
  for (std::size_t q : candidates) {
    const Eigen::Vector3f& c = parts[q].centroid;
    const float t = (c - row.origin).dot(row.direction);
    const float beyond = std::max(row.first - t, t - row.last);
    if (beyond > 0 && beyond <= reachSpacings * row.spacing &&
        offLine(row, c) <= lineShare * row.spacing)
      out.push_back(q);
  }
  return out;
}

}  // namespace sagrid
