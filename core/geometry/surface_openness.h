// How open the space around a surface point is: the share of directions in which nothing of the
// mesh lies (ambient openness, the complement of ambient occlusion) and how far it is straight
// down and straight up to the next surface. An affordance is where a hand or a pot reaches it: a
// burner under open sky, a spout's tip over the free space of its basin, a knob on a front face;
// a place inside a cabinet or between an oven's walls is closed. Read on the more open side of
// the surface (a mesh's triangles may face either way), in the mesh's own z-up frame.
#pragma once

#include <Eigen/Core>
#include <limits>

namespace sagrid {

class SurfaceScene;
struct ClosestPoint;

struct SurfaceOpenness {
  float openness = 1;  // share of the side's hemisphere of directions that leave the mesh, [0, 1]
  float below = std::numeric_limits<float>::infinity();  // to the next surface straight down
  float above = std::numeric_limits<float>::infinity();  // and straight up (mesh units)
};

// At `at` (a closest point of `scene`), from just off the surface on each side (`offset` mesh
// units along the normal); the side where more directions leave the mesh is the outside (where as
// many leave on both, the side the triangle faces).
SurfaceOpenness surfaceOpenness(const SurfaceScene& scene, const ClosestPoint& at, float offset);

}  // namespace sagrid
