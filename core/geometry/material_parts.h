// The parts of a mesh by material: for each material, the connected parts of its triangles. In
// low-poly and product models a burner's zone, a knob or a tap's handle is often fused into one
// connected body but drawn in a material of its own, so these are the candidates a curator (or a
// part segmentation) looks at where connected parts alone say nothing.
#pragma once

#include <vector>

#include "core/geometry/connected_parts.h"

namespace sagrid {

struct Mesh;

struct MaterialPart {
  int material = -1;  // index into mesh.materials; -1 where the mesh has none
  ConnectedPart part;
};

// Every material's connected parts, materials in order, each material's parts largest first.
std::vector<MaterialPart> materialParts(const Mesh& mesh);

// The connected parts of each group of triangles (`groupOfTriangle`, one entry per triangle; a
// triangle with an out-of-range index belongs to none), groups in ascending order, each group's
// parts largest first; MaterialPart::material is the group.
std::vector<MaterialPart> groupParts(const Mesh& mesh, const std::vector<int>& groupOfTriangle);

// Appends to `parts` each of `more` that is not one of those it held before (the same triangle
// count and box), with `flag` set on it (ConnectedPart::byMaterial, ::byCrease).
void appendNewParts(std::vector<ConnectedPart>& parts, std::vector<ConnectedPart> more,
                    bool ConnectedPart::*flag);

// The mesh's parts as a segmentation finer than connectivity: every connected part, then every
// material's connected part that is not one of them (the same triangle count and box), so a knob
// or burner zone fused into the body but drawn in a material of its own is a part too. Any part
// of two materials is split so: a free-standing knob with a cap of another material also gives
// its cap and its base as parts (the smaller box wins where a point lies on both, partAt).
// Connected parts' order; a mesh of one material has only its connected parts.
std::vector<ConnectedPart> connectedAndMaterialParts(const Mesh& mesh);

}  // namespace sagrid
