// The axis about which a control part is most nearly a body of revolution. A rotary knob turns
// about its axis of rotational symmetry (issue 42), which is not always one of the view's axes: a
// knob on a sloped control panel leans with the panel. The axis is the direction for which the
// part's surface, turned about it through the surface's centroid by a few unrelated angles, lands
// back on itself most closely. The GUI offers it as the curator's axis ("Own axis") and
// `eval --parts` reports how far each marked axis lies from it.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace sagrid {

struct Mesh;

struct RevolutionAxis {
  Eigen::Vector3f axis = Eigen::Vector3f::UnitZ();  // unit length, through `centre`
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();  // the part surface's area-weighted centroid
  // How much of the turned surface lands off the surface: the share of samples over it that, turned
  // about the axis by any of a few angles, lie further than 1.5 sample spacings from every sample
  // (0: a body of revolution; a square prism about its axis reads several times more than a
  // cylinder of the same size).
  float misfit = 0;
  // The same about the reference direction the caller gave, sampled alike.
  std::optional<float> referenceMisfit;
  float length = 0;  // the part's extent along the axis
  float radius = 0;  // its largest distance from the axis
};

// The part of `triangles` (indices into `mesh`; out-of-range ones ignored) that is most nearly a
// body of revolution about which axis, and with `reference` how nearly it is one about that
// direction too; nullopt for a part without area, with non-finite positions or for a zero
// reference. Deterministic.
std::optional<RevolutionAxis> revolutionAxis(const Mesh& mesh, const std::vector<int>& triangles,
                                             const std::optional<Eigen::Vector3f>& reference = std::nullopt);

}  // namespace sagrid
