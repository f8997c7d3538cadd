#include "core/geometry/material_parts.h"

#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

#include "core/mesh/mesh.h"

namespace sagrid {

std::vector<MaterialPart> materialParts(const Mesh& mesh) {
  // Each material's triangles on its own vertices only (a copy of every position per material
  // would cost the vertex count times the material count).
  std::map<int, Mesh> byMaterial;
  std::map<int, std::unordered_map<int, int>> vertexIn;
  const int vertices = static_cast<int>(mesh.positions.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& corners = mesh.triangles[t];
    if (corners.minCoeff() < 0 || corners.maxCoeff() >= vertices) continue;
    const int material = t < mesh.triangleMaterials.size() ? mesh.triangleMaterials[t] : -1;
    Mesh& subset = byMaterial[material];
    auto& index = vertexIn[material];
    Eigen::Vector3i local;
    for (int c = 0; c < 3; ++c) {
      const auto [at, added] = index.emplace(corners[c], static_cast<int>(subset.positions.size()));
      if (added) subset.positions.push_back(mesh.positions[static_cast<std::size_t>(corners[c])]);
      local[c] = at->second;
    }
    subset.triangles.push_back(local);
  }
  std::vector<MaterialPart> result;
  for (const auto& [material, subset] : byMaterial) {
    for (ConnectedPart& part : connectedParts(subset))
      result.push_back({material, std::move(part)});
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
