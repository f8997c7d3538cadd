// Rows of equal parts: a range's knobs stand on one line. A row's last control is sometimes a
// larger copy of the others (a real propane range's oven knob, 1.23 times its burner knobs, one
// and a half spacings beyond them); it is a scaled copy on the row's line, not a part of its own.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/geometry/connected_parts.h"

namespace sagrid {

// The line of a row of parts: centroids at origin + t * direction, t from `first` to `last`;
// `spacing` is the mean gap between neighbours along it.
struct PartRow {
  Eigen::Vector3f origin = Eigen::Vector3f::Zero();
  Eigen::Vector3f direction = Eigen::Vector3f::UnitX();
  float first = 0, last = 0, spacing = 0;
};

// The row that the parts of `family` (at least 3) form when every centroid lies within
// `lineShare` of the spacing from the line through the outermost two; nullopt otherwise (a
// square of burner caps, a grid, parts at one place).
std::optional<PartRow> partRow(const std::vector<std::size_t>& family,
                               const std::vector<ConnectedPart>& parts, float lineShare);

// The parts of `candidates` (a family's scaled copies: PartCopies with a maxScale) that continue
// `row` beyond its ends: centroid within `lineShare` of the spacing from the line and at most
// `reachSpacings` spacings beyond the nearer end.
std::vector<std::size_t> rowContinuations(const PartRow& row,
                                          const std::vector<std::size_t>& candidates,
                                          const std::vector<ConnectedPart>& parts, float lineShare,
                                          float reachSpacings);

}  // namespace sagrid
