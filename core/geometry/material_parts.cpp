#include "core/geometry/material_parts.h"

#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

#include "core/mesh/mesh.h"

namespace sagrid {

std::vector<MaterialPart> groupParts(const Mesh& mesh, const std::vector<int>& groupOfTriangle) {
  // Each group's triangles on its own vertices only (a copy of every position per group would
  // cost the vertex count times the group count).
  std::map<int, Mesh> byGroup;
  std::map<int, std::unordered_map<int, int>> vertexIn;
  const int vertices = static_cast<int>(mesh.positions.size());
  for (std::size_t t = 0; t < mesh.triangles.size() && t < groupOfTriangle.size(); ++t) {
    const auto& corners = mesh.triangles[t];
    const int group = groupOfTriangle[t];
    if (corners.minCoeff() < 0 || corners.maxCoeff() >= vertices) continue;
    Mesh& subset = byGroup[group];
    auto& index = vertexIn[group];
    Eigen::Vector3i local;
    for (int c = 0; c < 3; ++c) {
      const auto [at, added] = index.emplace(corners[c], static_cast<int>(subset.positions.size()));
      if (added) subset.positions.push_back(mesh.positions[static_cast<std::size_t>(corners[c])]);
      local[c] = at->second;
    }
    subset.triangles.push_back(local);
  }
  std::vector<MaterialPart> result;
  for (const auto& [group, subset] : byGroup) {
    for (ConnectedPart& part : connectedParts(subset)) result.push_back({group, std::move(part)});
  }
  return result;
}

std::vector<MaterialPart> materialParts(const Mesh& mesh) {
  std::vector<int> material(mesh.triangles.size(), -1);
  for (std::size_t t = 0; t < material.size() && t < mesh.triangleMaterials.size(); ++t)
    material[t] = mesh.triangleMaterials[t];
  return groupParts(mesh, material);
}

void appendNewParts(std::vector<ConnectedPart>& parts, std::vector<ConnectedPart> more,
                    bool ConnectedPart::*flag) {
  using Key = std::tuple<int, float, float, float, float, float, float>;
  const auto keyOf = [](const ConnectedPart& p) {
    return Key{p.triangles,     p.box.min().x(), p.box.min().y(), p.box.min().z(),
               p.box.max().x(), p.box.max().y(), p.box.max().z()};
  };
  std::set<Key> known;
  for (const auto& part : parts) known.insert(keyOf(part));
  for (auto& part : more)
    if (!known.count(keyOf(part))) {
      part.*flag = true;
      parts.push_back(std::move(part));
    }
}

std::vector<ConnectedPart> connectedAndMaterialParts(const Mesh& mesh) {
  std::vector<ConnectedPart> parts = connectedParts(mesh);
  if (mesh.materials.size() < 2 || mesh.triangleMaterials.empty()) return parts;
  std::vector<ConnectedPart> byMaterial;
  for (auto& m : materialParts(mesh)) byMaterial.push_back(std::move(m.part));
  appendNewParts(parts, std::move(byMaterial), &ConnectedPart::byMaterial);
  return parts;
}

}  // namespace sagrid
