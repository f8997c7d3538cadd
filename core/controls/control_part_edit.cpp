#include "core/controls/control_part_edit.h"

#include <algorithm>
#include <set>


namespace sagrid {

namespace {

struct Membership {
  std::vector<bool> inPart;
  std::vector<bool> partVertex, outsideVertex;  // welded vertices touched by part / other triangles
};

Membership membership(const TriangleComponents& welded, const std::vector<int>& triangles) {
  Membership m{std::vector<bool>(welded.ofTriangle.size(), false), {}, {}};
  for (int t : triangles)
    if (t >= 0 && static_cast<std::size_t>(t) < m.inPart.size()) m.inPart[static_cast<std::size_t>(t)] = true;
  m.partVertex.assign(welded.weldedPositions.size(), false);
  m.outsideVertex.assign(welded.weldedPositions.size(), false);
  for (std::size_t t = 0; t < welded.ofTriangle.size(); ++t) {
    if (welded.ofTriangle[t] < 0) continue;
    for (int v : welded.weldedCorners[t])
      (m.inPart[t] ? m.partVertex : m.outsideVertex)[static_cast<std::size_t>(v)] = true;
  }
  return m;
}

template <typename Keep>
std::vector<int> trianglesWhere(const TriangleComponents& welded, Keep keep) {
  std::vector<int> out;
  for (std::size_t t = 0; t < welded.ofTriangle.size(); ++t)
    if (welded.ofTriangle[t] >= 0 && keep(t)) out.push_back(static_cast<int>(t));
  return out;
}

}  // namespace

PartEditSurface::PartEditSurface(const Mesh& mesh) : welded(triangleComponents(mesh)) {
  around.resize(welded.weldedPositions.size());
  for (std::size_t t = 0; t < welded.ofTriangle.size(); ++t)
    if (welded.ofTriangle[t] >= 0)
      for (int v : welded.weldedCorners[t]) around[static_cast<std::size_t>(v)].push_back(static_cast<int>(t));
}

std::vector<int> grownPart(const PartEditSurface& surface, const std::vector<int>& triangles) {
  const TriangleComponents& welded = surface.welded;
  const Membership m = membership(welded, triangles);
  return trianglesWhere(welded, [&](std::size_t t) {
    if (m.inPart[t]) return true;
    for (int v : welded.weldedCorners[t])
      if (m.partVertex[static_cast<std::size_t>(v)]) return true;
    return false;
  });
}

std::vector<int> grownPart(const Mesh& mesh, const std::vector<int>& triangles) {
  return grownPart(PartEditSurface(mesh), triangles);
}

std::vector<int> shrunkPart(const PartEditSurface& surface, const std::vector<int>& triangles) {
  const TriangleComponents& welded = surface.welded;
  const Membership m = membership(welded, triangles);
  std::vector<int> inner = trianglesWhere(welded, [&](std::size_t t) {
    if (!m.inPart[t]) return false;
    for (int v : welded.weldedCorners[t])
      if (m.outsideVertex[static_cast<std::size_t>(v)]) return false;
    return true;
  });
  return inner.empty() ? trianglesWhere(welded, [&](std::size_t t) { return bool(m.inPart[t]); })
                       : inner;
}

std::vector<int> shrunkPart(const Mesh& mesh, const std::vector<int>& triangles) {
  return shrunkPart(PartEditSurface(mesh), triangles);
}

std::vector<int> brushedPart(const PartEditSurface& surface, const std::vector<int>& triangles,
                             int hitTriangle, const Eigen::Vector3f& hit, float radius, bool add) {
  const TriangleComponents& welded = surface.welded;
  std::set<int> part(triangles.begin(), triangles.end());
  if (hitTriangle < 0 || static_cast<std::size_t>(hitTriangle) >= welded.ofTriangle.size())
    return {part.begin(), part.end()};
  const auto inside = [&](int t) {
    for (int v : welded.weldedCorners[static_cast<std::size_t>(t)])
      if ((welded.weldedPositions[static_cast<std::size_t>(v)] - hit).norm() > radius) return false;
    return true;
  };
  std::vector<bool> seen(welded.ofTriangle.size(), false);
  std::vector<int> stack{hitTriangle};
  seen[static_cast<std::size_t>(hitTriangle)] = true;
  while (!stack.empty()) {
    const int t = stack.back();
    stack.pop_back();
    if (add) part.insert(t);
    else part.erase(t);
    if (welded.ofTriangle[static_cast<std::size_t>(t)] < 0) continue;
    for (int v : welded.weldedCorners[static_cast<std::size_t>(t)])
      for (int n : surface.around[static_cast<std::size_t>(v)])
        if (!seen[static_cast<std::size_t>(n)] && inside(n)) {
          seen[static_cast<std::size_t>(n)] = true;
          stack.push_back(n);
        }
  }
  return {part.begin(), part.end()};
}

std::vector<int> brushedPart(const Mesh& mesh, const std::vector<int>& triangles, int hitTriangle,
                             const Eigen::Vector3f& hit, float radius, bool add) {
  return brushedPart(PartEditSurface(mesh), triangles, hitTriangle, hit, radius, add);
}

}  // namespace sagrid
