// An object with its controls moved as a simulator would move them: each hinged part turned by an
// angle about its axis through its pivot, each slide pressed by a distance along its axis. The
// parts' triangles get vertices of their own (a fused knob's seam stays with the body), so the
// body keeps its shape. For looking at what an export will do (`sagrid info --turn`).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "core/controls/control_part.h"
#include "core/mesh/mesh.h"

namespace sagrid {

// The rigid motion of `part`: turned by `angle` about its axis through its pivot (a hinge), else
// pressed `press` along its axis.
Eigen::Affine3f controlMotion(const ControlPart& part, float angle, float press);

// How far a button travels when pressed home, metres: the exports' press joint's range
// (core/export/control_geometry.h) and the turned preview's press.
inline constexpr double kButtonTravel = 0.004;

// How far a button is shown pressed (mesh units of a mesh of `metersPerUnit`) while hinges turn by
// `angle`: home (kButtonTravel) at any angle but 0.
float pressAtTurn(float angle, double metersPerUnit);

// `parts` in the mesh's frame and units; discs (no triangles) move nothing.
Mesh turnControls(const Mesh& mesh, const std::vector<ControlPart>& parts, float angle,
                  float press);

}  // namespace sagrid
