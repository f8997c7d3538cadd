#include "core/controls/control_part_edit.h"

#include <algorithm>

#include "core/geometry/triangle_components.h"

namespace sagrid {

namespace {

struct Membership {
  TriangleComponents welded;
  std::vector<bool> inPart;
  std::vector<bool> partVertex, outsideVertex;  // welded vertices touched by part / other triangles
};

Membership membership(const Mesh& mesh, const std::vector<int>& triangles) {
  Membership m{triangleComponents(mesh), std::vector<bool>(mesh.triangles.size(), false), {}, {}};
  for (int t : triangles)
    if (t >= 0 && static_cast<std::size_t>(t) < m.inPart.size()) m.inPart[static_cast<std::size_t>(t)] = true;
  m.partVertex.assign(m.welded.weldedPositions.size(), false);
  m.outsideVertex.assign(m.welded.weldedPositions.size(), false);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (m.welded.ofTriangle[t] < 0) continue;
    for (int v : m.welded.weldedCorners[t])
      (m.inPart[t] ? m.partVertex : m.outsideVertex)[static_cast<std::size_t>(v)] = true;
  }
  return m;
}

template <typename Keep>
std::vector<int> trianglesWhere(const Membership& m, Keep keep) {
  std::vector<int> out;
  for (std::size_t t = 0; t < m.inPart.size(); ++t)
    if (m.welded.ofTriangle[t] >= 0 && keep(t)) out.push_back(static_cast<int>(t));
  return out;
}

}  // namespace

std::vector<int> grownPart(const Mesh& mesh, const std::vector<int>& triangles) {
  const Membership m = membership(mesh, triangles);
  return trianglesWhere(m, [&](std::size_t t) {
    if (m.inPart[t]) return true;
    for (int v : m.welded.weldedCorners[t])
      if (m.partVertex[static_cast<std::size_t>(v)]) return true;
    return false;
  });
}

std::vector<int> shrunkPart(const Mesh& mesh, const std::vector<int>& triangles) {
  const Membership m = membership(mesh, triangles);
  std::vector<int> inner = trianglesWhere(m, [&](std::size_t t) {
    if (!m.inPart[t]) return false;
    for (int v : m.welded.weldedCorners[t])
      if (m.outsideVertex[static_cast<std::size_t>(v)]) return false;
    return true;
  });
  return inner.empty() ? trianglesWhere(m, [&](std::size_t t) { return bool(m.inPart[t]); }) : inner;
}

}  // namespace sagrid
