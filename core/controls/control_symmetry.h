// The axis about which a control part is most nearly a body of revolution. A rotary knob turns
// about its axis of rotational symmetry (issue 42), which is not always one of the view's axes: a
// knob on a sloped control panel leans with the panel. The axis is the direction for which the
// part's surface, turned about it through the surface's centroid by a few unrelated angles, lands
// back on itself most closely. The GUI offers it as the curator's axis for a knob (the Points
// panel's "own" button) and `eval --parts` reports how far each marked knob's axis lies from it.
// The part is turned about its area centroid: a pointer or a flat on one side pulls that centroid
// off the true axis, and the true axis then fits less well than it would about its own centre.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace sagrid {

struct Mesh;

struct RevolutionAxis {
  Eigen::Vector3f axis = Eigen::Vector3f::UnitZ();  // unit length, through `centre`
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();  // the part surface's area-weighted centroid
  // How much of the turned surface lands off the surface: of about a hundred samples spread over it
  // by area, each turned about the axis by each of three angles, the share (of those sample-angle
  // pairs) landing further than 1.5 sample spacings from every sample. 0: a body of revolution; a
  // square prism reads well above a cylinder of its size about its best axis.
  float misfit = 0;
  // The same about the reference direction the caller gave, sampled alike.
  std::optional<float> referenceMisfit;
  float length = 0;  // the part's extent along the axis (over its triangles' corners)
  float radius = 0;  // their largest distance from the axis
};

// The axis about which the part of `triangles` (indices into `mesh`; out-of-range ones ignored) is
// most nearly a body of revolution, and with `reference` how nearly it is one about that direction
// too; nullopt for a part without area, with non-finite positions or for a zero reference.
// Deterministic; the cost does not grow with the part's triangle count beyond reading them.
std::optional<RevolutionAxis> revolutionAxis(const Mesh& mesh, const std::vector<int>& triangles,
                                             const std::optional<Eigen::Vector3f>& reference = std::nullopt);

}  // namespace sagrid
