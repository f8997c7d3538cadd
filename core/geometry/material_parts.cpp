#include "core/geometry/material_parts.h"

#include <map>

#include "core/mesh/mesh.h"

namespace sagrid {

std::vector<MaterialPart> materialParts(const Mesh& mesh) {
  std::map<int, Mesh> byMaterial;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int material = t < mesh.triangleMaterials.size() ? mesh.triangleMaterials[t] : -1;
    Mesh& subset = byMaterial[material];
    if (subset.positions.empty()) subset.positions = mesh.positions;  // shared vertex indices
    subset.triangles.push_back(mesh.triangles[t]);
  }
  std::vector<MaterialPart> result;
  for (const auto& [material, subset] : byMaterial) {
    for (ConnectedPart& part : connectedParts(subset)) result.push_back({material, std::move(part)});
  }
  return result;
}

}  // namespace sagrid
