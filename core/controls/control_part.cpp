#include "core/controls/control_part.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include "core/controls/control_symmetry.h"
#include "core/geometry/closest_point_on_triangle.h"
#include "core/geometry/connected_parts.h"
#include "core/geometry/point_grid.h"
#include "core/geometry/principal_axes.h"
#include "core/geometry/surface_scene.h"
#include "core/geometry/triangle_components.h"
#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

// Components whose boxes come this close (a share of the object's diagonal) touch: a knob's
// pointer on its cap, a skirt under it.
constexpr float kTouchShare = 0.01f;
// Components within the part's box grown by this share of its diagonal go with it.
constexpr float kWithShare = 0.25f;
// A grown part reaches at most this far from its point: a share of the distance to the nearest
// other control and of the object's diagonal.
constexpr float kGrowSpacingShare = 0.45f;
constexpr float kGrowDiagonalShare = 0.05f;
// Grown triangles that stand out of the panel by less than this share of the tallest do not
// belong to the control (the panel around it).
constexpr float kStandOutShare = 0.15f;
// A region standing out by less than this share of its radius is printed on the panel.
constexpr float kFlatShare = 0.08f;
// A part whose height along its axis is under this share of its radius is pressed, not turned.
constexpr float kButtonShare = 0.3f;
// A knob takes its own axis of rotational symmetry where this much more of its surface (as a
// share) lands back on itself turned about that axis than about the panel's normal.
constexpr float kOwnAxisMargin = 0.1f;
// ... and where it lies at least this far from the panel's normal.
constexpr float kOwnAxisApartDegrees = 30.0f;
// A part this many times longer than wide across its axis is a lever.
constexpr float kLeverElongation = 2.2f;
// Below this, the direction out of a lever's holder lies along the lever: it lifts upwards.
constexpr float kLiftMinimum = 0.3f;
// A lever's ends: the vertices within this share of its length from each end.
constexpr float kLeverEndShare = 0.15f;
// What a part's vertices touch: the surface within this share of the part's diagonal; and how
// much the touched normals must agree (the length of their sum per touch) to tell a panel.
constexpr float kContactShare = 0.1f;
constexpr float kContactAgreement = 0.5f;
// Touched normals within this many degrees of each other face as one panel.
constexpr float kPanelConeDegrees = 10.0f;
// A knob without a panel turns about its principal direction within this (cosine) of the way out.
constexpr float kAxisOfShape = 0.8f;
// Touched normals alike to this (per component of the unit normal) are counted as one.
constexpr float kNormalBin = 0.01f;
// A lever's held end this many times wider than its free end is a hub it turns with.
constexpr float kHubShare = 2.0f;
// A lever's free end stands further from what holds it than its held end by at least this share of
// its length; a long part whose ends lie nearer alike is held along its length (a grip).
constexpr float kHeldEndShare = 0.1f;
// A low-poly part's faces are sampled at most this many times for what they touch.
constexpr double kMaxFaceSamples = 20000;
// A grip turns about its holder's axis where that runs within this many degrees of square to it.
constexpr float kGripAcrossDegrees = 30.0f;
// A part whose faces' normals sum to more than this share of its area is an open sheet facing
// one way (a flat key), not a closed or two-sided part.
constexpr float kSheetFacing = 0.5f;
// A button's way out of what holds it is trusted when it runs at least this much (cosine) along
// the button's thinnest direction.
constexpr float kAlongThin = 0.5f;
// A disc cut around a printed key: this share of the grown radius.
constexpr float kDiscShare = 0.5f;

constexpr float radians(float degrees) { return degrees * static_cast<float>(M_PI) / 180.0f; }

struct Surface {
  const Mesh& mesh;
  std::vector<Eigen::Vector3f> centroids;
  std::vector<float> areas;
  std::vector<bool> valid;
  float totalArea = 0;
  float diagonal = 0;

  explicit Surface(const Mesh& m) : mesh(m) {
    const std::size_t n = m.triangles.size();
    areas = triangleAreas(m);  // 0 where a corner is missing
    centroids.resize(n), valid.assign(n, false);
    for (std::size_t t = 0; t < n; ++t) {
      const Eigen::Vector3i& tri = m.triangles[t];
      bool ok = true;
      for (int c = 0; c < 3; ++c)
        ok = ok && tri[c] >= 0 && static_cast<std::size_t>(tri[c]) < m.positions.size();
      if (!ok) continue;
      valid[t] = true;
      centroids[t] = (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0f;
      totalArea += areas[t];
    }
    const Eigen::AlignedBox3f box = m.bounds();
    diagonal = box.isEmpty() ? 0.0f : box.diagonal().norm();
  }
  const Eigen::Vector3f& corner(std::size_t t, int c) const {
    return mesh.positions[static_cast<std::size_t>(mesh.triangles[t][c])];
  }
  Eigen::Vector3f closestOn(std::size_t t, const Eigen::Vector3f& p) const {
    return closestPointOnTriangle(p, corner(t, 0), corner(t, 1), corner(t, 2));
  }
};

// The triangle nearest `p` among those `keep` accepts; -1 when there is none.
template <typename Keep>
int nearestTriangle(const Surface& s, const Eigen::Vector3f& p, Keep keep,
                    Eigen::Vector3f* closest = nullptr) {
  int best = -1;
  float bestDistance = std::numeric_limits<float>::infinity();
  for (std::size_t t = 0; t < s.valid.size(); ++t) {
    if (!s.valid[t] || !keep(t)) continue;
    const Eigen::Vector3f q = s.closestOn(t, p);
    const float d = (q - p).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d, best = static_cast<int>(t);
      if (closest) *closest = q;
    }
  }
  return best;
}

std::vector<int> distinctVertices(const Mesh& mesh, const std::vector<int>& triangles) {
  std::vector<int> vertices;
  for (int t : triangles)
    for (int c = 0; c < 3; ++c) vertices.push_back(mesh.triangles[static_cast<std::size_t>(t)][c]);
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

// Principal directions of points, largest spread first.
struct Principal {
  Eigen::Vector3f mean = Eigen::Vector3f::Zero();
  Eigen::Matrix3f directions = Eigen::Matrix3f::Identity();  // columns, largest spread first
  Eigen::Vector3f spread = Eigen::Vector3f::Zero();          // standard deviations
};

Principal principalOf(const std::vector<Eigen::Vector3f>& points) {
  const PrincipalAxes axes = principalAxes(points);
  return {axes.mean.cast<float>(), axes.axes.cast<float>(), axes.spread.cast<float>()};
}

// Any unit vector perpendicular to `n`.
Eigen::Vector3f perpendicular(const Eigen::Vector3f& n) {
  const Eigen::Vector3f other =
      std::abs(n.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  return n.cross(other).normalized();
}

struct ComponentStats {
  Eigen::AlignedBox3f box;
  float area = 0;
  Eigen::Vector3d weightedCentroid = Eigen::Vector3d::Zero();
  Eigen::Vector3f centroid() const {
    if (area > 0) return (weightedCentroid / area).cast<float>();
    return box.center();
  }
};

std::vector<ComponentStats> componentStats(const Surface& s, const TriangleComponents& c) {
  std::vector<ComponentStats> stats(static_cast<std::size_t>(c.count));
  for (std::size_t t = 0; t < c.ofTriangle.size(); ++t) {
    if (c.ofTriangle[t] < 0) continue;
    ComponentStats& st = stats[static_cast<std::size_t>(c.ofTriangle[t])];
    for (int k = 0; k < 3; ++k) st.box.extend(s.corner(t, k));
    st.area += s.areas[t];
    st.weightedCentroid += static_cast<double>(s.areas[t]) * s.centroids[t].cast<double>();
  }
  return stats;
}

std::size_t nearestPoint(const Eigen::Vector3f& x, const std::vector<Eigen::Vector3f>& points) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if ((points[i] - x).squaredNorm() < (points[best] - x).squaredNorm()) best = i;
  return best;
}

struct PointContext {
  const SurfaceScene& scene;
  std::size_t index;
  const std::vector<Eigen::Vector3f>& points;
  const std::vector<int>& seeds;  // each point's nearest triangle
  float spacing;                  // distance to the nearest other point (the diagonal if none)
};

// One labelling of the triangles (connected, or connected within a material) as every point's
// search reads it: each component's box, area and centroid, and the component each point lies
// on. Computed once per labelling, not per point.
struct Labelling {
  const TriangleComponents& components;
  std::vector<ComponentStats> stats;
  std::vector<int> seeds;  // per point: its component, or -1
};

// The component a point lies on: of the components whose box, grown by the touch distance, holds
// it, the one with the smallest box (a knob, not the panel it is sunk into); else the component of
// its nearest triangle.
int seedComponent(const std::vector<ComponentStats>& stats, const TriangleComponents& c,
                  const Eigen::Vector3f& p, int nearestTriangle, float touch) {
  int best = -1;
  float bestDiagonal = std::numeric_limits<float>::infinity();
  for (std::size_t k = 0; k < stats.size(); ++k) {
    const float diagonal = stats[k].box.diagonal().norm();
    if (stats[k].box.exteriorDistance(p) <= touch && diagonal < bestDiagonal)
      best = static_cast<int>(k), bestDiagonal = diagonal;
  }
  if (best < 0 && nearestTriangle >= 0) best = c.ofTriangle[static_cast<std::size_t>(nearestTriangle)];
  return best;
}

Labelling labellingOf(const Surface& s, const TriangleComponents& c,
                      const std::vector<Eigen::Vector3f>& points,
                      const std::vector<int>& nearestTriangles) {
  Labelling l{c, componentStats(s, c), {}};
  const float touch = kTouchShare * s.diagonal;
  for (std::size_t i = 0; i < points.size(); ++i)
    l.seeds.push_back(seedComponent(l.stats, c, points[i], nearestTriangles[i], touch));
  return l;
}

// Whether `p` lies well inside `component`: clear of every surface (by kTouchShare of the
// object's diagonal: not a point on a face), and along the six axis directions from it the surface
// first met is the component's all ways but at most one (a knob open at its base, standing on a
// panel or on what is not in the file).
bool surroundedBy(const SurfaceScene& scene, const TriangleComponents& c, int component,
                  const Eigen::Vector3f& p, float diagonal) {
  if (!(scene.closestPoint(p).distance > kTouchShare * diagonal)) return false;
  int elsewhere = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const float sign : {1.0f, -1.0f}) {
      const auto hit = scene.intersect(p, sign * Eigen::Vector3f::Unit(axis), 1e-6f * diagonal);
      if (!hit || hit->triangle < 0 || c.ofTriangle[static_cast<std::size_t>(hit->triangle)] != component)
        ++elsewhere;
    }
  return elsewhere <= 1;
}

// The point's part from one labelling of the triangles: the component it lies on with the small
// components inside its box, each nearer this point than any other; none when that component is
// too large (unless the point lies well inside it) or another point lies on it too.
std::optional<std::vector<int>> componentPart(const Surface& s, const Labelling& l,
                                              const PointContext& ctx) {
  const std::vector<ComponentStats>& stats = l.stats;
  const int seed = l.seeds[ctx.index];
  if (seed < 0) return std::nullopt;
  std::vector<bool> foreign(stats.size(), false);  // another point lies on it
  for (std::size_t i = 0; i < l.seeds.size(); ++i)
    if (i != ctx.index && l.seeds[i] >= 0) foreign[static_cast<std::size_t>(l.seeds[i])] = true;
  const float maxDiagonal = std::min(kSmallPartDiagonal * s.diagonal, 2.0f * ctx.spacing);
  const auto small = [&](std::size_t k) {
    return !foreign[k] && stats[k].box.diagonal().norm() <= maxDiagonal &&
           stats[k].area <= kMaxControlAreaShare * s.totalArea &&
           nearestPoint(stats[k].centroid(), ctx.points) == ctx.index;
  };
  const auto seedIndex = static_cast<std::size_t>(seed);
  // A point inside a closed component (a large knob's centre) names that component, however large,
  // as long as it is no body (at most kMaxControlAreaShare of the area) and no other point's.
  const auto enclosing = [&] {
    return !foreign[seedIndex] && stats[seedIndex].area <= kMaxControlAreaShare * s.totalArea &&
           surroundedBy(ctx.scene, l.components, seed, ctx.points[ctx.index], s.diagonal);
  };
  if (!small(seedIndex) && !enclosing()) return std::nullopt;
  // What belongs with it lies within its box grown a little: a pointer, a cap, a ring; not a bar
  // or a rail it is mounted on.
  Eigen::AlignedBox3f reach = stats[seedIndex].box;
  const Eigen::Vector3f grow = Eigen::Vector3f::Constant(
      std::max(kTouchShare * s.diagonal, kWithShare * stats[seedIndex].box.diagonal().norm()));
  reach.extend(reach.min() - grow).extend(reach.max() + grow);
  std::vector<bool> member(stats.size(), false);
  for (std::size_t k = 0; k < stats.size(); ++k)
    member[k] = k == seedIndex || (reach.contains(stats[k].box) && small(k));
  const std::vector<int>& ofTriangle = l.components.ofTriangle;
  std::vector<int> triangles;
  for (std::size_t t = 0; t < ofTriangle.size(); ++t)
    if (ofTriangle[t] >= 0 && member[static_cast<std::size_t>(ofTriangle[t])])
      triangles.push_back(static_cast<int>(t));
  return triangles;
}

struct GrownRegion {
  std::vector<int> triangles;  // standing out of the panel; empty when flat
  Eigen::Vector3f panelNormal = Eigen::Vector3f::UnitZ();
  float radius = 0;
};

// The surface around the point within the grow radius (by distance: a soup of loose triangles
// grows as a welded surface does), less what does not stand out of the panel around it (the
// panel: the ring of triangles just outside).
GrownRegion grownRegion(const Surface& s, const PointContext& ctx) {
  GrownRegion out;
  const Eigen::Vector3f& p = ctx.points[ctx.index];
  out.radius = std::min(kGrowSpacingShare * ctx.spacing, kGrowDiagonalShare * s.diagonal);
  std::vector<int> region, ring;
  for (std::size_t t = 0; t < s.valid.size(); ++t) {
    if (!s.valid[t]) continue;
    const float d = (s.centroids[t] - p).norm();
    if (d <= out.radius) region.push_back(static_cast<int>(t));
    else if (d <= 2.0f * out.radius) ring.push_back(static_cast<int>(t));
  }
  if (ring.empty()) {  // nothing around it: the region is all there is
    std::sort(region.begin(), region.end());
    out.triangles = region;
    return out;
  }
  std::vector<Eigen::Vector3f> ringPoints;
  for (int t : ring) ringPoints.push_back(s.centroids[static_cast<std::size_t>(t)]);
  const Principal panel = principalOf(ringPoints);
  Eigen::Vector3f normal = panel.directions.col(2);
  if ((p - panel.mean).dot(normal) < 0) normal = -normal;
  out.panelNormal = normal;
  float tallest = 0;
  for (int t : region)
    for (int k = 0; k < 3; ++k)
      tallest = std::max(tallest, (s.corner(static_cast<std::size_t>(t), k) - panel.mean).dot(normal));
  if (tallest < kFlatShare * out.radius) return out;  // printed on the panel
  for (int t : region)
    if ((s.centroids[static_cast<std::size_t>(t)] - panel.mean).dot(normal) > kStandOutShare * tallest)
      out.triangles.push_back(t);
  std::sort(out.triangles.begin(), out.triangles.end());
  return out;
}

float areaOf(const Surface& s, const std::vector<int>& triangles) {
  float area = 0;
  for (int t : triangles) area += s.areas[static_cast<std::size_t>(t)];
  return area;
}

// The area-weighted sum of the triangles' normals: the way an open sheet looks (its area times its
// normal for a flat one), near zero for a closed or two-sided part.
Eigen::Vector3f facingOf(const Surface& s, const std::vector<int>& triangles) {
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (int t : triangles) {
    const auto u = static_cast<std::size_t>(t);
    sum += 0.5f * (s.corner(u, 1) - s.corner(u, 0)).cross(s.corner(u, 2) - s.corner(u, 0));
  }
  return sum;
}

// The vertices within kLeverEndShare of a lever's length from one end: their centroid and how far
// they reach from the lever's line.
struct EndSlab {
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  float width = 0;
};

EndSlab endSlab(const std::vector<Eigen::Vector3f>& vertices, const Eigen::Vector3f& centre,
                const Eigen::Vector3f& along, float end, float length) {
  EndSlab slab;
  int count = 0;
  for (const auto& v : vertices)
    if (std::abs((v - centre).dot(along) - end) <= kLeverEndShare * length) slab.centroid += v, ++count;
  if (count == 0) return slab;
  slab.centroid /= static_cast<float>(count);
  for (const auto& v : vertices) {
    if (std::abs((v - centre).dot(along) - end) > kLeverEndShare * length) continue;
    const Eigen::Vector3f d = v - slab.centroid;
    slab.width = std::max(slab.width, (d - d.dot(along) * along).norm());
  }
  return slab;
}

// The way a part (`inPart`, its shape) stands out of what holds it: from the nearest point of the
// rest of the surface to its centre; none where nothing apart holds it or what does runs through
// its centre (a key level with its panel).
std::optional<Eigen::Vector3f> awayFromHolder(const Surface& s, const std::vector<bool>& inPart,
                                              const Principal& shape) {
  Eigen::Vector3f holder = shape.mean;
  const int holderTriangle =
      nearestTriangle(s, shape.mean, [&](std::size_t t) { return !inPart[t]; }, &holder);
  const Eigen::Vector3f out = shape.mean - holder;
  if (holderTriangle < 0 || out.norm() < 1e-6f * std::max(s.diagonal, 1e-12f)) return std::nullopt;
  return out.normalized();
}

// How near a part's points (`points`, its vertices) another surface counts as touching it: a
// share of the part's size.
float touchDistance(const Surface& s, const std::vector<Eigen::Vector3f>& points) {
  Eigen::AlignedBox3f box;
  for (const auto& p : points) box.extend(p);
  return std::max(kContactShare * box.diagonal().norm(), 1e-6f * s.diagonal);
}

// What a part touches: the triangles of the surface apart from it within kContactShare of the
// part's size of its vertices, each one's normal turned towards the part's `centre` and counted
// once per vertex touching it; triangles facing alike (to kNormalBin) merged into one entry.
struct Contact {
  std::vector<std::pair<Eigen::Vector3f, float>> normals;  // a unit normal, the vertices touching so
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();           // the normals times their touches
  float touches = 0;
  std::vector<int> triangles;                              // those touched
};

Contact contactOf(const Surface& s, const std::vector<bool>& inPart,
                  const std::vector<Eigen::Vector3f>& vertices, const Eigen::Vector3f& centre) {
  Contact contact;
  if (vertices.empty()) return contact;
  Eigen::AlignedBox3f box;
  for (const auto& v : vertices) box.extend(v);
  if (!box.min().allFinite() || !box.max().allFinite()) return contact;
  const float touch = touchDistance(s, vertices);
  Eigen::AlignedBox3f near = box;
  near.min().array() -= touch, near.max().array() += touch;
  const PointGrid grid(vertices, box, touch);
  std::map<std::array<int, 3>, std::size_t> bins;  // a binned normal -> its entry in `normals`
  for (std::size_t t = 0; t < s.valid.size(); ++t) {
    if (!s.valid[t] || inPart[t]) continue;
    Eigen::AlignedBox3f triangle;
    for (int c = 0; c < 3; ++c) triangle.extend(s.corner(t, c));
    if (!near.intersects(triangle)) continue;
    Eigen::Vector3f normal = (s.corner(t, 1) - s.corner(t, 0)).cross(s.corner(t, 2) - s.corner(t, 0));
    if (normal.norm() <= 0) continue;
    normal.normalize();
    if (normal.dot(centre - s.centroids[t]) < 0) normal = -normal;
    float touches = 0;
    triangle.min().array() -= touch, triangle.max().array() += touch;
    grid.forEachWithin(triangle, [&](int v) {
      const Eigen::Vector3f& p = vertices[static_cast<std::size_t>(v)];
      if ((s.closestOn(t, p) - p).norm() <= touch) ++touches;
    });
    if (touches == 0) continue;
    contact.triangles.push_back(static_cast<int>(t));
    contact.sum += touches * normal, contact.touches += touches;
    // Triangles facing alike (a flat panel's) count as one normal: the panel search is quadratic
    // in the normals kept.
    const Eigen::Vector3i bin = (normal / kNormalBin).array().round().cast<int>();
    const auto [at, added] =
        bins.emplace(std::array<int, 3>{bin.x(), bin.y(), bin.z()}, contact.normals.size());
    if (added) {
      contact.normals.emplace_back(touches * normal, touches);
    } else {
      contact.normals[at->second].first += touches * normal;
      contact.normals[at->second].second += touches;
    }
  }
  for (auto& [normal, touches] : contact.normals) normal.normalize();
  return contact;
}

// Points over the faces of `triangles` about `spacing` apart (a barycentric grid on each), at most
// kMaxFaceSamples in all (the spacing widened to fit): what a low-poly part touches between its
// corners.
std::vector<Eigen::Vector3f> faceSamples(const Surface& s, const std::vector<int>& triangles, float spacing) {
  const auto divisions = [&](std::size_t t, float step) {
    float longest = 0;
    for (int c = 0; c < 3; ++c)
      longest = std::max(longest, (s.corner(t, (c + 1) % 3) - s.corner(t, c)).norm());
    const float d = std::ceil(longest / std::max(step, 1e-12f));
    return std::isfinite(d) ? std::clamp(static_cast<int>(std::min(d, 4096.0f)), 1, 4096) : 1;
  };
  const auto usable = [&](std::size_t t) {
    return s.valid[t] && s.corner(t, 0).allFinite() && s.corner(t, 1).allFinite() &&
           s.corner(t, 2).allFinite();
  };
  const auto count = [&](float step) {
    double n = 0;
    for (int t : triangles) {
      if (!usable(static_cast<std::size_t>(t))) continue;
      const double d = divisions(static_cast<std::size_t>(t), step);
      n += (d + 1) * (d + 2) / 2;
    }
    return n;
  };
  for (double n = count(spacing); n > kMaxFaceSamples; n = count(spacing))
    spacing *= static_cast<float>(std::sqrt(n / kMaxFaceSamples)) * 1.01f;
  std::vector<Eigen::Vector3f> samples;
  for (int t : triangles) {
    const auto u = static_cast<std::size_t>(t);
    if (!usable(u)) continue;
    const int n = divisions(u, spacing);
    const Eigen::Vector3f a = s.corner(u, 0), ab = s.corner(u, 1) - a, ac = s.corner(u, 2) - a;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        samples.push_back(a + (static_cast<float>(i) / n) * ab + (static_cast<float>(j) / n) * ac);
  }
  return samples;
}

// The normal of the panel a part stands on, from what it touches (contactOf): the way most of the
// contact faces (the mean of the normals within kPanelConeDegrees of the one with most such
// contact: the panel, not the sides of a ring or bezel around the part). None where nothing
// touches it or the touched normals cancel (a part held all round).
std::optional<Eigen::Vector3f> standingNormal(const Contact& contact) {
  if (contact.touches == 0 || contact.sum.norm() < kContactAgreement * contact.touches)
    return std::nullopt;
  const float cone = std::cos(radians(kPanelConeDegrees));
  float most = 0;
  Eigen::Vector3f panel = contact.sum;
  for (const auto& [normal, touches] : contact.normals) {
    float count = 0;
    Eigen::Vector3f alike = Eigen::Vector3f::Zero();
    for (const auto& [other, otherTouches] : contact.normals)
      if (normal.dot(other) >= cone) count += otherTouches, alike += otherTouches * other;
    if (count > most) most = count, panel = alike;
  }
  return panel.normalized();
}

// A part's vertices, their principal shape and the way it stands out of what holds it.
struct PartShape {
  std::vector<Eigen::Vector3f> vertices;
  Principal shape;
  std::vector<bool> inPart;             // per triangle of the mesh
  std::optional<Eigen::Vector3f> held;  // awayFromHolder
};

// The distinct vertices of a part's triangles.
std::vector<Eigen::Vector3f> partVertices(const Mesh& mesh, const std::vector<int>& triangles) {
  std::vector<Eigen::Vector3f> vertices;
  for (int v : distinctVertices(mesh, triangles))
    vertices.push_back(mesh.positions[static_cast<std::size_t>(v)]);
  return vertices;
}

PartShape partShapeOf(const Surface& s, const std::vector<int>& triangles) {
  PartShape part;
  part.vertices = partVertices(s.mesh, triangles);
  part.shape = principalOf(part.vertices);
  part.inPart.assign(s.valid.size(), false);
  for (int t : triangles) part.inPart[static_cast<std::size_t>(t)] = true;
  part.held = awayFromHolder(s, part.inPart, part.shape);
  return part;
}

// Where a button goes when pressed: into what holds it (against `out`). Where the key is flat and
// what holds it lies level with it or over its edge, `out` runs along the key: then along the key's
// thinnest direction, against the way it faces when drawn as one open sheet, else towards the
// middle of the object (a key on a top is pressed down, one on a front panel back).
Eigen::Vector3f pressDirection(const Surface& s, const std::vector<int>& triangles,
                               const Principal& shape, const std::optional<Eigen::Vector3f>& out) {
  const Eigen::Vector3f thin = shape.directions.col(2).normalized();
  const Eigen::Vector3f facing = facingOf(s, triangles);
  if (facing.norm() > kSheetFacing * areaOf(s, triangles))
    return facing.dot(thin) > 0 ? Eigen::Vector3f(-thin) : thin;
  if (out && std::abs(out->dot(thin)) >= kAlongThin) return -*out;
  const Eigen::Vector3f inward = s.mesh.bounds().center() - shape.mean;
  return inward.dot(thin) >= 0 ? thin : Eigen::Vector3f(-thin);
}

// A long part (its vertices about `centre`, long `along`) as a lever turning about its held end,
// the end nearer the rest of the surface: its motion, pivot and axis written into `part`. False
// (nothing written) where it `touches` what holds it (contactOf) and its two ends lie alike near
// the rest (their gaps differ by less than kHeldEndShare of its length): no end holds it, it is
// held along its length (a grip). A part touching nothing (a low-poly bar whose only vertices are
// its ends) is not judged a grip.
bool leverOnItsEnd(const Surface& s, ControlPart& part, const std::vector<Eigen::Vector3f>& vertices,
                   const Eigen::Vector3f& centre, const std::vector<bool>& inPart,
                   Eigen::Vector3f along, const Eigen::Vector3f& out, bool touches) {
  float first = std::numeric_limits<float>::infinity(), last = -first;
  for (const auto& v : vertices) {
    const float t = (v - centre).dot(along);
    first = std::min(first, t), last = std::max(last, t);
  }
  const auto endGap = [&](float end) {
    const Eigen::Vector3f slab = endSlab(vertices, centre, along, end, last - first).centroid;
    Eigen::Vector3f nearest = slab;
    if (nearestTriangle(s, slab, [&](std::size_t t) { return !inPart[t]; }, &nearest) < 0)
      return 0.0f;
    return (nearest - slab).norm();
  };
  const float firstGap = endGap(first), lastGap = endGap(last);
  if (touches && std::abs(firstGap - lastGap) < kHeldEndShare * (last - first)) return false;
  part.motion = ControlMotion::Lever;
  if (lastGap < firstGap) along = -along, std::swap(first, last), first = -first, last = -last;
  part.pivot = centre + first * along;
  // A lever on a hub (a cartridge's cap, much wider than the lever's free end) turns with the hub
  // about the hub's axis, out of what holds it.
  const EndSlab held = endSlab(vertices, centre, along, first, last - first);
  const EndSlab free = endSlab(vertices, centre, along, last, last - first);
  if (held.width > kHubShare * std::max(free.width, 1e-12f)) {
    part.pivot = held.centroid;
    part.axis = out;
    return true;
  }
  // It lifts away from what holds it: about the axis across it and that direction (up where it
  // points straight out of its holder).
  Eigen::Vector3f lift = out - out.dot(along) * along;
  if (lift.norm() < kLiftMinimum) lift = Eigen::Vector3f::UnitZ() - along.z() * along;
  const Eigen::Vector3f axis = along.cross(lift);
  part.axis = axis.norm() > 1e-6f ? axis.normalized() : perpendicular(along);
  return true;
}

// The axis a grip long `along` turns about: that of what holds it, the surface it touches
// (`contact`), about which that surface is most nearly a body of revolution (a knob's face under a
// bar, a stem under a cross or through a bar), where it runs across the grip (within
// kGripAcrossDegrees of square to `along`), taken square to it (the grip turns across its
// length; the fit of a holder touched only in patches leans a little); none where nothing touches
// it or the holder's axis runs along the grip. Facing `out`. The holder's fit is not checked: a
// grip laid on a flat panel turns about the panel's normal, the axis a flat patch fits best.
std::optional<Eigen::Vector3f> gripAxis(const Surface& s, const Contact& contact,
                                        const Eigen::Vector3f& along, const Eigen::Vector3f& out) {
  const auto holder = revolutionAxis(s.mesh, contact.triangles);
  if (!holder) return std::nullopt;
  if (std::abs(holder->axis.dot(along)) > std::sin(radians(kGripAcrossDegrees)))
    return std::nullopt;
  return facingWay((holder->axis - holder->axis.dot(along) * along).normalized(), out);
}

// The axis a knob turns about: the normal of the panel it stands on; where the panel cannot be
// told (it touches nothing, or is held all round), its own principal direction nearest the way out
// of the nearest surface apart from it (`out`), else that way. Then its own axis of rotational
// symmetry where that clearly says the axis above is another (the panel misread): turned about it
// clearly more of its surface lands back on itself, it lies far from the axis above (a few
// degrees' nudge by the fit of a part that is no body of revolution, a square tap handle, is not
// worth more than the panel's plane), and the part is no longer along it than across (an arm or a
// stem is nearly symmetric about its length).
Eigen::Vector3f knobAxis(const Surface& s, const std::vector<int>& triangles, const Principal& shape,
                         const std::optional<Eigen::Vector3f>& panel, const Eigen::Vector3f& out) {
  Eigen::Vector3f axis = out.normalized();
  if (panel) {
    axis = *panel;
  } else {
    float best = kAxisOfShape;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3f d = shape.directions.col(i).normalized();
      const float c = std::abs(d.dot(out));
      if (c > best) best = c, axis = facingWay(d, out);
    }
  }
  const auto own = revolutionAxis(s.mesh, triangles, axis);
  if (own && own->referenceMisfit && *own->referenceMisfit - own->misfit >= kOwnAxisMargin &&
      std::abs(own->axis.dot(axis)) <= std::cos(radians(kOwnAxisApartDegrees)) &&
      own->length <= 2.0f * own->radius)
    axis = facingWay(own->axis, axis);
  return axis;
}

ControlPart describe(const Surface& s, std::vector<int> triangles, PartOrigin origin) {
  ControlPart part;
  part.origin = origin;
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
  const PartShape partShape = partShapeOf(s, triangles);
  const std::vector<Eigen::Vector3f>& vertices = partShape.vertices;
  const Principal& shape = partShape.shape;
  const Eigen::Vector3f centre = shape.mean;
  const std::vector<bool>& inPart = partShape.inPart;
  const std::optional<Eigen::Vector3f>& held = partShape.held;
  // The way it stands out of what holds it: away from the nearest surface apart from it, else
  // (held by nothing apart) its thinnest direction. Its shape is judged across the normal of the
  // panel it stands on where one is found (the nearest point of what holds it can lie on a bezel
  // or an edge beside the part: a round knob then looks long across that way).
  const Eigen::Vector3f out = held.value_or(Eigen::Vector3f(shape.directions.col(2).normalized()));
  const Contact contact = contactOf(s, inPart, vertices, centre);
  const std::optional<Eigen::Vector3f> panel = standingNormal(contact);
  const Eigen::Vector3f standing = panel ? facingWay(*panel, out) : out;

  // Height along `standing` and the shape across it.
  float low = std::numeric_limits<float>::infinity(), high = -low;
  std::vector<Eigen::Vector3f> across;
  for (const auto& v : vertices) {
    const float h = (v - centre).dot(standing);
    low = std::min(low, h), high = std::max(high, h);
    across.push_back(v - h * standing);
  }
  const Principal flat = principalOf(across);
  float radius = 0;
  for (const auto& a : across) radius = std::max(radius, (a - flat.mean).norm());
  part.radius = radius;
  part.pivot = centre;
  // Long and thin, whether across what holds it (a top lever) or out of it (a side lever).
  const bool long3d = shape.spread[0] > kLeverElongation * std::max(shape.spread[1], 1e-12f);
  const bool longAcross = flat.spread[0] > kLeverElongation * std::max(flat.spread[1], 1e-12f);
  if (long3d || longAcross) {
    const Eigen::Vector3f along = (long3d ? shape.directions.col(0) : flat.directions.col(0)).normalized();
    // A low-poly part may touch what holds it only between its corners (a bar through a stem).
    const Contact holding =
        contact.triangles.empty()
            ? contactOf(s, inPart, faceSamples(s, triangles, 0.5f * touchDistance(s, vertices)), centre)
            : contact;
    if (leverOnItsEnd(s, part, vertices, centre, inPart, along, out, !holding.triangles.empty())) {
      part.triangles = std::move(triangles);
      return part;
    }
    // Held alike at both ends there is no end to pivot about: a grip (a bar across a knob's face,
    // a cross on a stem, a bar through one) turns as a knob, with what holds it.
    part.motion = ControlMotion::Knob;
    const auto grip = gripAxis(s, holding, along, out);
    part.axis = grip ? *grip : knobAxis(s, triangles, shape, panel, out);
  } else if (high - low < kButtonShare * radius) {
    part.motion = ControlMotion::Button;
    part.axis = pressDirection(s, triangles, shape, held);
  } else {
    part.motion = ControlMotion::Knob;
    part.axis = knobAxis(s, triangles, shape, panel, out);
  }
  part.triangles = std::move(triangles);
  return part;
}

}  // namespace

const char* toString(ControlMotion motion) {
  switch (motion) {
    case ControlMotion::Knob: return "knob";
    case ControlMotion::Lever: return "lever";
    case ControlMotion::Button: return "button";
  }
  return "knob";
}

const char* toString(PartOrigin origin) {
  switch (origin) {
    case PartOrigin::Connected: return "connected";
    case PartOrigin::Material: return "material";
    case PartOrigin::Grown: return "grown";
    case PartOrigin::Disc: return "disc";
    case PartOrigin::Marked: return "marked";
  }
  return "connected";
}

std::optional<ControlMotion> parseControlMotion(const std::string& text) {
  for (ControlMotion m : {ControlMotion::Knob, ControlMotion::Lever, ControlMotion::Button})
    if (text == toString(m)) return m;
  return std::nullopt;
}

std::optional<PartOrigin> parsePartOrigin(const std::string& text) {
  for (PartOrigin o : {PartOrigin::Connected, PartOrigin::Material, PartOrigin::Grown,
                       PartOrigin::Disc, PartOrigin::Marked})
    if (text == toString(o)) return o;
  return std::nullopt;
}

Eigen::Vector3f pressDirection(const Mesh& mesh, const std::vector<int>& triangles) {
  const Surface s(mesh);
  const PartShape part = partShapeOf(s, triangles);
  if (part.vertices.empty()) return Eigen::Vector3f::UnitZ();
  return pressDirection(s, triangles, part.shape, part.held);
}

ControlPart describeControlPart(const Mesh& mesh, std::vector<int> triangles, PartOrigin origin) {
  const Surface surface(mesh);
  triangles.erase(std::remove_if(triangles.begin(), triangles.end(),
                                 [&](int t) {
                                   return t < 0 || static_cast<std::size_t>(t) >= surface.valid.size() ||
                                          !surface.valid[static_cast<std::size_t>(t)];
                                 }),
                  triangles.end());
  return describe(surface, std::move(triangles), origin);
}

Eigen::Vector3f partCentre(const Mesh& mesh, const std::vector<int>& triangles) {
  std::vector<int> valid;
  for (int t : triangles)
    if (t >= 0 && static_cast<std::size_t>(t) < mesh.triangles.size()) valid.push_back(t);
  const std::vector<Eigen::Vector3f> vertices = partVertices(mesh, valid);
  return vertices.empty() ? Eigen::Vector3f::Zero() : principalOf(vertices).mean;
}

ControlParts findControlParts(const Mesh& mesh, const std::vector<Eigen::Vector3f>& points) {
  if (points.empty()) return {};  // no scene to build
  return findControlParts(mesh, SurfaceScene(mesh), points);
}

ControlParts findControlParts(const Mesh& mesh, const SurfaceScene& scene,
                              const std::vector<Eigen::Vector3f>& points) {
  ControlParts result;
  result.parts.resize(points.size());
  result.warnings.resize(points.size());
  const Surface surface(mesh);
  if (points.empty() || !(surface.totalArea > 0)) {
    for (auto& warning : result.warnings) warning = "the mesh has no surface; site only";
    return result;
  }
  std::vector<int> seeds;
  for (const ClosestPoint& c : scene.closestPoints(points)) seeds.push_back(c.triangle);
  const TriangleComponents connected = triangleComponents(mesh, false);
  const Labelling byConnection = labellingOf(surface, connected, points, seeds);
  const bool materials = std::adjacent_find(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(),
                                            std::not_equal_to<>()) != mesh.triangleMaterials.end();
  const std::optional<TriangleComponents> materialComponents =
      materials ? std::optional<TriangleComponents>(triangleComponents(mesh, true)) : std::nullopt;
  const std::optional<Labelling> byMaterial =
      materialComponents ? std::optional<Labelling>(labellingOf(surface, *materialComponents, points, seeds))
                         : std::nullopt;
  for (std::size_t i = 0; i < points.size(); ++i) {
    float spacing = surface.diagonal;
    for (std::size_t j = 0; j < points.size(); ++j)
      if (j != i) spacing = std::min(spacing, (points[j] - points[i]).norm());
    const PointContext ctx{scene, i, points, seeds, spacing};
    if (byMaterial) {
      if (auto tris = componentPart(surface, *byMaterial, ctx)) {
        result.parts[i] = describe(surface, std::move(*tris), PartOrigin::Material);
        continue;
      }
    }
    if (auto tris = componentPart(surface, byConnection, ctx)) {
      result.parts[i] = describe(surface, std::move(*tris), PartOrigin::Connected);
      continue;
    }
    GrownRegion grown = grownRegion(surface, ctx);
    if (areaOf(surface, grown.triangles) > kMaxControlAreaShare * surface.totalArea) {
      result.warnings[i] = "its part would take most of the object; site only";
      continue;
    }
    if (!grown.triangles.empty()) {
      result.parts[i] = describe(surface, std::move(grown.triangles), PartOrigin::Grown);
      continue;
    }
    ControlPart disc;  // printed on the panel: a thin disc pressed into it
    disc.origin = PartOrigin::Disc;
    disc.motion = ControlMotion::Button;
    disc.axis = -grown.panelNormal;
    disc.pivot = points[i];
    disc.radius = kDiscShare * grown.radius;
    result.parts[i] = disc;
    result.warnings[i] =
        "nothing stands out of the surface there (printed?); a thin disc slides in its place";
  }
  return result;
}

}  // namespace sagrid
