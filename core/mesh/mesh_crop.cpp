#include "core/mesh/mesh_crop.h"

namespace sagrid {
namespace {

// A vertex with every attribute the mesh has (unused ones stay zero).
struct CropVertex {
  Eigen::Vector3f position, normal = Eigen::Vector3f::Zero(), color = Eigen::Vector3f::Zero();
  Eigen::Vector2f uv = Eigen::Vector2f::Zero();
};

CropVertex lerp(const CropVertex& a, const CropVertex& b, float t) {
  return {a.position + t * (b.position - a.position), a.normal + t * (b.normal - a.normal),
          a.color + t * (b.color - a.color), a.uv + t * (b.uv - a.uv)};
}

// Sutherland-Hodgman: the part of the polygon with sign * (p[axis] - bound) <= 0.
std::vector<CropVertex> clip(const std::vector<CropVertex>& polygon, int axis, float bound,
                             float sign) {
  std::vector<CropVertex> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const CropVertex& a = polygon[i];
    const CropVertex& b = polygon[(i + 1) % polygon.size()];
    const float da = sign * (a.position[axis] - bound), db = sign * (b.position[axis] - bound);
    if (da <= 0) out.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(lerp(a, b, da / (da - db)));
  }
  return out;
}

}  // namespace

Mesh cropMesh(const Mesh& mesh, const Eigen::AlignedBox3f& box) {
  Mesh crop = mesh.withoutGeometry();
  const bool normals = mesh.normals.size() == mesh.positions.size();
  const bool uvs = mesh.uvs.size() == mesh.positions.size();
  const bool colors = mesh.colors.size() == mesh.positions.size();
  auto vertex = [&](int v) {
    CropVertex c;
    c.position = mesh.positions[v];
    if (normals) c.normal = mesh.normals[v];
    if (uvs) c.uv = mesh.uvs[v];
    if (colors) c.color = mesh.colors[v];
    return c;
  };
  auto add = [&](const CropVertex& c) {
    crop.positions.push_back(c.position);
    if (normals) crop.normals.push_back(c.normal.normalized());
    if (uvs) crop.uvs.push_back(c.uv);
    if (colors) crop.colors.push_back(c.color);
    return static_cast<int>(crop.positions.size() - 1);
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    Eigen::AlignedBox3f triangleBox;
    for (int k = 0; k < 3; ++k) triangleBox.extend(mesh.positions[tri[k]]);
    if (!box.intersects(triangleBox)) continue;
    std::vector<CropVertex> polygon{vertex(tri[0]), vertex(tri[1]), vertex(tri[2])};
    if (!box.contains(triangleBox))
      for (int axis = 0; axis < 3 && polygon.size() >= 3; ++axis) {
        polygon = clip(polygon, axis, box.min()[axis], -1.0f);
        if (polygon.size() >= 3) polygon = clip(polygon, axis, box.max()[axis], 1.0f);
      }
    if (polygon.size() < 3) continue;
    const int first = add(polygon[0]);
    int previous = add(polygon[1]);
    for (std::size_t k = 2; k < polygon.size(); ++k) {
      const int next = add(polygon[k]);
      crop.triangles.emplace_back(first, previous, next);
      if (!mesh.triangleMaterials.empty())
        crop.triangleMaterials.push_back(mesh.triangleMaterials[t]);
      previous = next;
    }
  }
  return crop;
}

std::optional<Eigen::AlignedBox3f> regionAround(const std::vector<Eigen::Vector3f>& points,
                                                const Eigen::AlignedBox3f& bounds, float margin,
                                                float maxShare, std::string* why) {
  auto no = [why](const char* reason) -> std::optional<Eigen::AlignedBox3f> {
    if (why) *why = reason;
    return std::nullopt;
  };
  const float extent = bounds.sizes().maxCoeff();
  Eigen::AlignedBox3f box;
  for (const auto& p : points) box.extend(p);
  const Eigen::Vector3f grow = Eigen::Vector3f::Constant(margin * extent);
  box.min() -= grow;
  box.max() += grow;
  box = box.intersection(bounds);
  if (box.isEmpty()) return no("the region around the points lies outside the object");
  if (box.sizes().maxCoeff() > maxShare * extent)
    return no("the points spread over most of the object");
  return box;
}

}  // namespace sagrid
