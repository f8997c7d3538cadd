#include "core/mesh/geometry_identity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/common/error.h"

namespace sagrid {

namespace {

// The triangles' corners in the file's frame (three per triangle) and their box.
struct FileCorners {
  std::vector<Eigen::Vector3d> corners;
  Eigen::AlignedBox3d box;
};

FileCorners fileCorners(const Mesh& mesh) {
  const int vertexCount = static_cast<int>(mesh.positions.size());
  FileCorners out;
  out.corners.reserve(mesh.triangles.size() * 3);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (v < 0 || v >= vertexCount)
        throw InvalidArgument("geometry outline: triangle " + std::to_string(t) + " names vertex " +
                              std::to_string(v) + " of a mesh with " + std::to_string(vertexCount));
      const Eigen::Vector3d p =
          zUpToFile(mesh.positions[std::size_t(v)], mesh.fileUp).cast<double>();
      if (!p.allFinite())
        throw InvalidArgument("geometry outline: vertex " + std::to_string(v) + " is not finite");
      out.corners.push_back(p);
      out.box.extend(p);
    }
  }
  return out;
}

std::optional<GeometryOutline> outlineOf(const FileCorners& corners) {
  if (corners.corners.empty()) return std::nullopt;
  GeometryOutline outline;
  outline.triangles = corners.corners.size() / 3;
  outline.size = corners.box.sizes();
  if (!(outline.extent() > 0)) return std::nullopt;
  return outline;
}

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

// One mesh's triangles relative to its box origin, with a grid of their centres.
class TriangleGrid {
 public:
  TriangleGrid(const FileCorners& file, double cell) : m_cell(cell) {
    m_corners.reserve(file.corners.size());
    for (const Eigen::Vector3d& p : file.corners) m_corners.push_back(p - file.box.min());
    for (std::size_t t = 0; t < triangles(); ++t) m_cells[cellOf(centre(t))].push_back(t);
  }

  std::size_t triangles() const { return m_corners.size() / 3; }
  const Eigen::Vector3d& corner(std::size_t t, int k) const {
    return m_corners[3 * t + std::size_t(k)];
  }
  Eigen::Vector3d centre(std::size_t t) const {
    return (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0;
  }

  // Triangle `t` of `other` and triangle `mine` of this grid have the same corners within a cell,
  // in the same winding, from any first corner.
  bool same(const TriangleGrid& other, std::size_t t, std::size_t mine) const {
    for (int start = 0; start < 3; ++start) {
      bool all = true;
      for (int k = 0; k < 3 && all; ++k)
        all = (other.corner(t, k) - corner(mine, (k + start) % 3)).cwiseAbs().maxCoeff() <= m_cell;
      if (all) return true;
    }
    return false;
  }

  // Some triangle of this grid is triangle `t` of `other`. Corners within a cell put the centres
  // within a cell, so the centre's cell and its neighbours hold every candidate.
  bool holds(const TriangleGrid& other, std::size_t t) const {
    const Cell c = cellOf(other.centre(t));
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = m_cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == m_cells.end()) continue;
          for (std::size_t mine : it->second)
            if (same(other, t, mine)) return true;
        }
    return false;
  }

 private:
  Cell cellOf(const Eigen::Vector3d& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / m_cell)),
            static_cast<std::int64_t>(std::floor(p.y() / m_cell)),
            static_cast<std::int64_t>(std::floor(p.z() / m_cell))};
  }

  double m_cell;
  std::vector<Eigen::Vector3d> m_corners;
  std::unordered_map<Cell, std::vector<std::size_t>, CellHash> m_cells;
};

}  // namespace

std::optional<GeometryOutline> geometryOutline(const Mesh& mesh) {
  return outlineOf(fileCorners(mesh));
}

bool sameOutline(const GeometryOutline& a, const GeometryOutline& b, double relativeTolerance) {
  const double within = relativeTolerance * std::max(a.extent(), b.extent());
  return a.triangles == b.triangles && (a.size - b.size).cwiseAbs().maxCoeff() <= within;
}

std::optional<GeometryMatch> matchGeometry(const Mesh& from, const Mesh& to,
                                           double relativeTolerance) {
  if (!(relativeTolerance > 0 && relativeTolerance < 1))
    throw InvalidArgument("same geometry: the tolerance " + std::to_string(relativeTolerance) +
                          " is not between 0 and 1 (a share of the object's size)");
  const FileCorners a = fileCorners(from), b = fileCorners(to);
  const auto outlineA = outlineOf(a), outlineB = outlineOf(b);
  if (!outlineA || !outlineB || !sameOutline(*outlineA, *outlineB, relativeTolerance))
    return std::nullopt;

  const double cell = relativeTolerance * std::max(outlineA->extent(), outlineB->extent());
  const TriangleGrid gridA(a, cell), gridB(b, cell);
  // Both ways: equal counts alone would let one triangle of A stand for two of B.
  for (std::size_t t = 0; t < gridA.triangles(); ++t)
    if (!gridB.holds(gridA, t)) return std::nullopt;
  for (std::size_t t = 0; t < gridB.triangles(); ++t)
    if (!gridA.holds(gridB, t)) return std::nullopt;

  GeometryMatch match;
  match.offset = b.box.min() - a.box.min();
  match.sameTriangleOrder = true;
  for (std::size_t t = 0; t < gridA.triangles() && match.sameTriangleOrder; ++t)
    match.sameTriangleOrder = gridB.same(gridA, t, t);
  return match;
}

}  // namespace sagrid
