// The curator's edits of a control part's triangles (the GUI's Grow and Shrink): growing adds
// every triangle sharing a vertex position with the part; shrinking drops the part's triangles on
// its border (those sharing a vertex position with a triangle outside it). Sorted, no duplicates.
#pragma once

#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid {

std::vector<int> grownPart(const Mesh& mesh, const std::vector<int>& triangles);
// Never empties a part: a part that is all border keeps its triangles.
std::vector<int> shrunkPart(const Mesh& mesh, const std::vector<int>& triangles);

}  // namespace sagrid
