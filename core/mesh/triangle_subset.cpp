#include "core/mesh/triangle_subset.h"

namespace sagrid {

Mesh triangleSubset(const Mesh& mesh, const std::vector<bool>& keep) {
  Mesh out = mesh.withoutGeometry();
  out.sha256 = mesh.sha256;
  const std::size_t vertices = mesh.positions.size();
  std::vector<int> renumbered(vertices, -1);
  const auto take = [&](int v) {
    int& id = renumbered[static_cast<std::size_t>(v)];
    if (id >= 0) return id;
    id = static_cast<int>(out.positions.size());
    const auto i = static_cast<std::size_t>(v);
    out.positions.push_back(mesh.positions[i]);
    if (mesh.normals.size() == vertices) out.normals.push_back(mesh.normals[i]);
    if (mesh.uvs.size() == vertices) out.uvs.push_back(mesh.uvs[i]);
    if (mesh.colors.size() == vertices) out.colors.push_back(mesh.colors[i]);
    return id;
  };
  const bool materials = mesh.triangleMaterials.size() == mesh.triangles.size();
  for (std::size_t t = 0; t < mesh.triangles.size() && t < keep.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    if (!keep[t]) continue;
    bool valid = true;
    for (int c = 0; c < 3; ++c)
      valid = valid && tri[c] >= 0 && static_cast<std::size_t>(tri[c]) < vertices;
    if (!valid) continue;
    out.triangles.emplace_back(take(tri[0]), take(tri[1]), take(tri[2]));
    if (materials) out.triangleMaterials.push_back(mesh.triangleMaterials[t]);
  }
  return out;
}

}  // namespace sagrid
