// Patches of a mesh's surface bounded by creases: triangles joined across an edge they share
// (vertices at the same position count as one) where the surface turns there by less than a crease
// angle. A burner's raised ring or cap, a key pressed into a panel, a knob's face modelled into one
// body with the rest are patches of their own where neither connectivity nor a material tells them
// apart: an over-segmentation the learned point decision takes candidates from (issue 40).
#pragma once

#include <vector>

#include "core/geometry/connected_parts.h"

namespace sagrid {

struct Mesh;

// Blender's auto-smooth default: a turn this sharp between faces reads as an edge, not a curve.
constexpr float kCreaseDegrees = 30.0f;

// Every patch, in the mesh's frame, largest triangle count first. Faces whose windings disagree
// (common in wild files) join as if they agreed; a triangle of no area joins none.
std::vector<ConnectedPart> creasePatches(const Mesh& mesh, float creaseDegrees = kCreaseDegrees);

}  // namespace sagrid
