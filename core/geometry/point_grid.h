// Points binned in a grid of cubes over a box, so that what lies near a small box or a point is
// found without looking at every point: the contact search of control parts (core/controls/
// control_part.cpp) and the symmetry search's nearest-sample distance (control_symmetry.cpp).
// Points outside the box fall into its border cells; the cells are enlarged where the box would
// need more than kMaxCellsPerSide of them a side, so memory stays bounded (queries stay exact,
// only slower).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace sagrid {

class PointGrid {
 public:
  static constexpr int kMaxCellsPerSide = 32;

  // `points` must outlive the grid.
  PointGrid(const std::vector<Eigen::Vector3f>& points, const Eigen::AlignedBox3f& box, float cell);

  // Calls f(i) for every point whose cell overlaps `query` (each once; some lie outside it).
  template <typename F>
  void forEachWithin(const Eigen::AlignedBox3f& query, F f) const {
    const Eigen::Vector3i lo = cellOf(query.min()), hi = cellOf(query.max());
    for (int z = lo.z(); z <= hi.z(); ++z)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int x = lo.x(); x <= hi.x(); ++x)
          for (int i : m_cells[static_cast<std::size_t>(index({x, y, z}))]) f(i);
  }

  // The distance from `p` to the nearest point, or `reach` where none lies nearer.
  float distanceWithin(const Eigen::Vector3f& p, float reach) const;

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3f& p) const;
  int index(const Eigen::Vector3i& c) const { return (c.z() * m_dims.y() + c.y()) * m_dims.x() + c.x(); }

  const std::vector<Eigen::Vector3f>& m_points;
  Eigen::Vector3f m_origin;
  float m_cell = 1;
  Eigen::Vector3i m_dims = Eigen::Vector3i::Ones();
  std::vector<std::vector<int>> m_cells;
};

// `v` turned to point the way `way` does (a hinge axis keeps its sense when replaced).
inline Eigen::Vector3f facingWay(const Eigen::Vector3f& v, const Eigen::Vector3f& way) {
  return v.dot(way) < 0 ? Eigen::Vector3f(-v) : v;
}

}  // namespace sagrid
