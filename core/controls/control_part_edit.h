// The curator's edits of a control part's triangles (the GUI's Grow, Shrink and brush): growing
// adds every triangle sharing a vertex position with the part; shrinking drops the part's triangles
// on its border (those sharing a vertex position with a triangle outside it); the brush adds or
// removes the surface around a clicked point. Sorted, no duplicates.
#pragma once

#include <vector>

#include "core/geometry/triangle_components.h"
#include "core/mesh/mesh.h"

namespace sagrid {

// A mesh's surface welded by position, with the triangles around each welded vertex: what Grow,
// Shrink and the brush walk over. Welding a large mesh costs far more than one edit, so the GUI
// keeps one per mesh; the overloads taking a Mesh weld it for that one call.
struct PartEditSurface {
  explicit PartEditSurface(const Mesh& mesh);
  TriangleComponents welded;
  std::vector<std::vector<int>> around;  // per welded vertex, the triangles using it
};

std::vector<int> grownPart(const PartEditSurface& surface, const std::vector<int>& triangles);
std::vector<int> grownPart(const Mesh& mesh, const std::vector<int>& triangles);
// Never empties a part: a part that is all border keeps its triangles.
std::vector<int> shrunkPart(const PartEditSurface& surface, const std::vector<int>& triangles);
std::vector<int> shrunkPart(const Mesh& mesh, const std::vector<int>& triangles);

// The brush: the triangles reached from `hitTriangle` over shared vertex positions without leaving
// the ball of `radius` (mesh units) around `hit` (every corner inside it; the hit triangle always),
// added to the part (`add`) or taken from it. What is not connected to the clicked surface (the
// panel behind a separate knob) is never brushed. A hit triangle the mesh lacks changes nothing.
std::vector<int> brushedPart(const PartEditSurface& surface, const std::vector<int>& triangles,
                             int hitTriangle, const Eigen::Vector3f& hit, float radius, bool add);
std::vector<int> brushedPart(const Mesh& mesh, const std::vector<int>& triangles, int hitTriangle,
                             const Eigen::Vector3f& hit, float radius, bool add);

}  // namespace sagrid
