#include "core/export/visual_parts.h"

#include <algorithm>
#include <functional>
#include <map>
#include <unordered_map>

namespace sagrid::exportdetail {

namespace {

// A sub-mesh of `mesh` with the given triangles, vertices renumbered in first-use order.
Mesh subMesh(const Mesh& mesh, const std::vector<int>& triangles) {
  Mesh part;
  std::unordered_map<int, int> remap;
  part.triangles.reserve(triangles.size());
  for (int t : triangles) {
    Eigen::Vector3i out;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      auto [it, inserted] = remap.emplace(v, static_cast<int>(part.positions.size()));
      if (inserted) part.positions.push_back(mesh.positions[v]);
      out[k] = it->second;
    }
    part.triangles.push_back(out);
  }
  return part;
}

std::size_t farthestFrom(const std::vector<Eigen::Vector3f>& points,
                         const std::function<float(const Eigen::Vector3f&)>& distance) {
  std::size_t best = 0;
  float bestDistance = -1.0f;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float d = distance(points[i]);
    if (d > bestDistance) bestDistance = d, best = i;
  }
  return best;
}

}  // namespace

bool spansVolume(const Mesh& mesh) {
  const auto& p = mesh.positions;
  if (p.size() < 4) return false;
  const Eigen::Vector3f a = p[0];
  const Eigen::Vector3f b = p[farthestFrom(p, [&](const auto& x) { return (x - a).norm(); })];
  const float diameter = (b - a).norm();
  if (diameter <= 0.0f) return false;
  const Eigen::Vector3f axis = (b - a) / diameter;
  const Eigen::Vector3f c = p[farthestFrom(p, [&](const auto& x) {
    const Eigen::Vector3f d = x - a;
    return (d - d.dot(axis) * axis).norm();
  })];
  const Eigen::Vector3f normal = axis.cross(c - a);
  if (normal.norm() <= 1e-6f * diameter * diameter) return false;
  const Eigen::Vector3f unitNormal = normal.normalized();
  float thickness = 0.0f;
  for (const auto& x : p) thickness = std::max(thickness, std::abs((x - a).dot(unitNormal)));
  return thickness > 1e-5f * diameter;
}

std::vector<MeshPart> visualParts(const Mesh& mesh, std::vector<std::string>& warnings) {
  // Triangles per material (-1: none), in material order.
  std::map<int, std::vector<int>> byMaterial;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const int m =
        t < static_cast<int>(mesh.triangleMaterials.size()) ? mesh.triangleMaterials[t] : -1;
    byMaterial[m >= 0 && m < static_cast<int>(mesh.materials.size()) ? m : -1].push_back(t);
  }
  struct Group {
    int material;
    std::vector<int> triangles;
  };
  std::vector<Group> solid;
  std::vector<int> flat;  // triangles of groups that span no volume on their own
  for (auto& [material, triangles] : byMaterial) {
    if (spansVolume(subMesh(mesh, triangles))) {
      solid.push_back({material, std::move(triangles)});
    } else {
      flat.insert(flat.end(), triangles.begin(), triangles.end());
    }
  }
  if (!flat.empty()) {
    if (spansVolume(subMesh(mesh, flat)) || solid.empty()) {
      solid.push_back({-1, std::move(flat)});
    } else {
      auto largest = std::max_element(solid.begin(), solid.end(), [](const auto& x, const auto& y) {
        return x.triangles.size() < y.triangles.size();
      });
      largest->triangles.insert(largest->triangles.end(), flat.begin(), flat.end());
    }
    if (byMaterial.size() > 1)
      warnings.push_back("flat mesh parts (no volume) were merged into other visual parts");
  }
  std::vector<MeshPart> parts;
  for (auto& group : solid) {
    std::sort(group.triangles.begin(), group.triangles.end());
    MeshPart part;
    part.name = "visual_" + std::to_string(parts.size());
    part.mesh = subMesh(mesh, group.triangles);
    if (group.material >= 0) part.color = mesh.materials[group.material].baseColor;
    parts.push_back(std::move(part));
  }
  if (parts.size() == 1 && !spansVolume(parts.front().mesh)) {
    warnings.push_back(
        "the mesh spans no volume (all in one plane): MuJoCo can show it but "
        "cannot compute its mass from it");
  }
  return parts;
}

}  // namespace sagrid::exportdetail
