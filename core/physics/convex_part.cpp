#include "core/physics/convex_part.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "core/common/third_party_warnings.h"
#include "core/geometry/principal_axes.h"
#include "core/mesh/mesh.h"

SAGRID_THIRD_PARTY_BEGIN
extern "C" {
#include <libqhull_r/qhull_ra.h>
}
SAGRID_THIRD_PARTY_END

namespace sagrid::physics {

namespace {

// Qhull reports problems on a FILE*; ours go nowhere (the caller gets nullopt and decides).
struct QuietFile {
  FILE* file = std::fopen("/dev/null", "w");
  ~QuietFile() {
    if (file) std::fclose(file);
  }
};

// Runs qhull on `coords` (x y z per point) with `options` and reads back the triangulated hull,
// oriented outwards. nullopt when qhull fails (flat or too few points).
std::optional<ConvexPart> runQhull(std::vector<double>& coords, const std::string& options) {
  QuietFile quiet;
  qhT qhStorage;
  qhT* qh = &qhStorage;
  qh_zero(qh, quiet.file);
  std::string command = "qhull " + options;
  const int exitCode = qh_new_qhull(qh, 3, static_cast<int>(coords.size() / 3), coords.data(),
                                    False, command.data(), nullptr, quiet.file);
  std::optional<ConvexPart> part;
  if (exitCode == 0) {
    part.emplace();
    std::vector<int> indexOfVertex(static_cast<std::size_t>(qh->vertex_id) + 1, -1);
    vertexT* vertex;
    FORALLvertices {
      indexOfVertex[vertex->id] = static_cast<int>(part->vertices.size());
      part->vertices.emplace_back(static_cast<float>(vertex->point[0]),
                                  static_cast<float>(vertex->point[1]),
                                  static_cast<float>(vertex->point[2]));
    }
    facetT* facet;
    FORALLfacets {
      if (qh_setsize(qh, facet->vertices) != 3) continue;  // "Qt" triangulates every facet
      Eigen::Vector3i tri;
      for (int c = 0; c < 3; ++c)
        tri[c] = indexOfVertex[static_cast<vertexT*>(facet->vertices->e[c].p)->id];
      const Eigen::Vector3d a = part->vertices[tri[0]].cast<double>();
      const Eigen::Vector3d n = (part->vertices[tri[1]].cast<double>() - a)
                                    .cross(part->vertices[tri[2]].cast<double>() - a);
      const Eigen::Vector3d outward(facet->normal[0], facet->normal[1], facet->normal[2]);
      if (n.dot(outward) < 0) std::swap(tri[1], tri[2]);
      part->triangles.push_back(tri);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int currentLong = 0, totalLong = 0;
  qh_memfreeshort(qh, &currentLong, &totalLong);
  if (part && (part->vertices.size() < 4 || part->triangles.size() < 4 || !(part->volume() > 0)))
    part.reset();
  return part;
}

// The points' extent along their three principal axes (largest first) and those axes.
struct PrincipalExtent {
  Eigen::Matrix3d axes;      // columns
  Eigen::Vector3d extent;    // max - min projection along each column
};

PrincipalExtent principalExtent(const std::vector<Eigen::Vector3f>& points) {
  PrincipalExtent result;
  result.axes = principalAxes(points).axes;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& p : points) {
    const Eigen::Vector3d q = result.axes.transpose() * p.cast<double>();
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  result.extent = hi - lo;
  return result;
}

}  // namespace

double ConvexPart::volume() const {
  double sixTimes = 0;
  for (const auto& t : triangles)
    sixTimes += vertices[t[0]].cast<double>().dot(
        vertices[t[1]].cast<double>().cross(vertices[t[2]].cast<double>()));
  return sixTimes / 6.0;
}

Eigen::Vector3d ConvexPart::centroid() const {
  double sixTimes = 0;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (const auto& t : triangles) {
    const Eigen::Vector3d a = vertices[t[0]].cast<double>(), b = vertices[t[1]].cast<double>(),
                          c = vertices[t[2]].cast<double>();
    const double v = a.dot(b.cross(c));
    sixTimes += v;
    weighted += v * (a + b + c) / 4.0;
  }
  return sixTimes != 0 ? Eigen::Vector3d(weighted / sixTimes) : Eigen::Vector3d::Zero();
}

bool ConvexPart::contains(const Eigen::Vector3f& p, float tolerance) const {
  for (const auto& t : triangles) {
    const Eigen::Vector3f a = vertices[t[0]];
    const Eigen::Vector3f n = (vertices[t[1]] - a).cross(vertices[t[2]] - a);
    const float length = n.norm();
    if (length == 0) continue;
    if ((p - a).dot(n) > tolerance * length) return false;
  }
  return !triangles.empty();
}

namespace {

std::optional<ConvexPart> hullOf(const std::vector<Eigen::Vector3f>& points, int maxVertices,
                                 bool joggle) {
  std::vector<double> coords;
  coords.reserve(points.size() * 3);
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  // "Qt": triangulated output. "TA<n>": stop after n points added to the initial simplex; Qhull
  // adds the farthest point first, so the result is the greedy best hull of that many vertices.
  std::string options = "Qt";
  if (maxVertices >= 4 && static_cast<int>(points.size()) > maxVertices)
    options += " TA" + std::to_string(maxVertices - 4);
  std::optional<ConvexPart> part = runQhull(coords, options);
  if (!part && joggle) part = runQhull(coords, options + " QJ");  // past precision trouble
  return part;
}

bool hasThinAxis(const PrincipalExtent& principal, float minThickness) {
  const double flatness = std::max(1e-5 * principal.extent[0], 0.25 * minThickness);
  return principal.extent[1] <= flatness || principal.extent[2] <= flatness;
}

}  // namespace

std::optional<ConvexPart> convexHull(const std::vector<Eigen::Vector3f>& points, int maxVertices,
                                     float minThickness) {
  if (points.size() < 2) return std::nullopt;
  // Most point sets are solid: hull them as they are and check the shape on the hull's few
  // vertices (same extents as the points).
  if (auto hull = hullOf(points, maxVertices, false))
    if (!hasThinAxis(principalExtent(hull->vertices), minThickness)) return hull;
  const PrincipalExtent principal = principalExtent(points);
  const double largest = principal.extent[0];
  if (!(largest > 0)) return std::nullopt;
  const double flatness = 1e-5 * largest;
  // Flat (or line-like) sets: offset copies of the points along the thin axes give a slab.
  std::vector<Eigen::Vector3f> solidPoints = points;
  for (int axis = 1; axis < 3; ++axis) {
    if (principal.extent[axis] > std::max(flatness, 0.25 * minThickness)) continue;
    if (minThickness <= 0) return std::nullopt;
    const Eigen::Vector3f offset =
        (principal.axes.col(axis) * (0.5 * minThickness - 0.5 * principal.extent[axis])).cast<float>();
    std::vector<Eigen::Vector3f> thick;
    thick.reserve(solidPoints.size() * 2);
    for (const auto& p : solidPoints) {
      thick.push_back(p + offset);
      thick.push_back(p - offset);
    }
    solidPoints.swap(thick);
  }
  return hullOf(solidPoints, maxVertices, true);
}

Mesh toMesh(const ConvexPart& part) {
  Mesh mesh;
  mesh.positions = part.vertices;
  mesh.triangles = part.triangles;
  return mesh;
}

}  // namespace sagrid::physics
