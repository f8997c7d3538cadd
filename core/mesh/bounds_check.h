// Whether a mesh's bounding box can be worked on in float coordinates at all: the check that
// import, normalization into the unit cube and the physics exports share, so a degenerate or
// far-away mesh gets one clear message naming its problem.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace sagrid {

// Why a bounding box cannot be normalized meaningfully, or nullopt when it can: empty, not
// finite, no extent (all vertices coincide), or so small against its distance from the origin
// that float coordinates cannot resolve a 64^3 grid on it (e.g. a 1 m object at 1e9).
std::optional<std::string> normalizationProblem(const Eigen::AlignedBox3f& box);

}  // namespace sagrid
