#include "core/geometry/material_parts.h"

#include <map>
#include <set>
#include <tuple>

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

namespace sagrid {

std::vector<ConnectedPart> connectedAndMaterialParts(const Mesh& mesh) {
  std::vector<ConnectedPart> parts = connectedParts(mesh);
  if (mesh.materials.size() < 2 || mesh.triangleMaterials.empty()) return parts;
  using Key = std::tuple<int, float, float, float, float, float, float>;
  const auto keyOf = [](const ConnectedPart& p) {
    return Key{p.triangles,     p.box.min().x(), p.box.min().y(), p.box.min().z(),
               p.box.max().x(), p.box.max().y(), p.box.max().z()};
  };
  std::set<Key> connected;
  for (const auto& part : parts) connected.insert(keyOf(part));
  for (auto& m : materialParts(mesh))
    if (!connected.count(keyOf(m.part))) {
      m.part.byMaterial = true;
      parts.push_back(std::move(m.part));
    }
  return parts;
}

}  // namespace sagrid
