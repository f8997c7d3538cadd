#include "core/geometry/point_grid.h"

#include <algorithm>
#include <cmath>

namespace sagrid {

PointGrid::PointGrid(const std::vector<Eigen::Vector3f>& points, const Eigen::AlignedBox3f& box,
                     float cell)
    : m_points(points), m_origin(box.min()) {
  const Eigen::Vector3f extent = box.sizes();
  m_cell = std::max({cell, extent.maxCoeff() / static_cast<float>(kMaxCellsPerSide), 1e-12f});
  for (int a = 0; a < 3; ++a)
    m_dims[a] = std::clamp(static_cast<int>(std::ceil(extent[a] / m_cell)), 1, kMaxCellsPerSide);
  m_cells.resize(static_cast<std::size_t>(m_dims.prod()));
  for (std::size_t i = 0; i < points.size(); ++i)
    m_cells[static_cast<std::size_t>(index(cellOf(points[i])))].push_back(static_cast<int>(i));
}

Eigen::Vector3i PointGrid::cellOf(const Eigen::Vector3f& p) const {
  Eigen::Vector3i c;
  for (int a = 0; a < 3; ++a)
    c[a] = std::clamp(static_cast<int>(std::floor((p[a] - m_origin[a]) / m_cell)), 0, m_dims[a] - 1);
  return c;
}

float PointGrid::distanceWithin(const Eigen::Vector3f& p, float reach) const {
  float best = reach * reach;
  const Eigen::Vector3f r = Eigen::Vector3f::Constant(reach);
  forEachWithin(Eigen::AlignedBox3f(p - r, p + r), [&](int i) {
    best = std::min(best, (m_points[static_cast<std::size_t>(i)] - p).squaredNorm());
  });
  return std::sqrt(best);
}

}  // namespace sagrid
