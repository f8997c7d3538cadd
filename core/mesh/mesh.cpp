#include "core/mesh/mesh.h"

#include <algorithm>
#include <cmath>

namespace sagrid {

namespace {
Eigen::Vector3f texel(const Texture& t, int x, int y) {
  x = ((x % t.width) + t.width) % t.width;
  y = ((y % t.height) + t.height) % t.height;
  const std::uint8_t* p = &t.rgba[(static_cast<std::size_t>(y) * t.width + x) * 4];
  return Eigen::Vector3f(p[0], p[1], p[2]) / 255.0f;
}
}  // namespace

Eigen::Vector3f Texture::sample(const Eigen::Vector2f& uv) const {
  if (width <= 0 || height <= 0) return Eigen::Vector3f::Ones();
  // A damaged file's UVs (NaN, or too large to turn into a texel index) sample nothing.
  if (!uv.allFinite() || uv.cwiseAbs().maxCoeff() > 1e6f) return Eigen::Vector3f::Ones();
  const float fx = uv.x() * width - 0.5f;
  const float fy = (1.0f - uv.y()) * height - 0.5f;
  const float x0 = std::floor(fx), y0 = std::floor(fy);
  const float ax = fx - x0, ay = fy - y0;
  const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  return (1 - ay) * ((1 - ax) * texel(*this, ix, iy) + ax * texel(*this, ix + 1, iy)) +
         ay * ((1 - ax) * texel(*this, ix, iy + 1) + ax * texel(*this, ix + 1, iy + 1));
}

Eigen::AlignedBox3f Mesh::bounds() const {
  Eigen::AlignedBox3f box;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) box.extend(positions[t[k]]);
  }
  return box;
}

Eigen::Vector3f Mesh::albedo(int tri, float u, float v) const {
  const Eigen::Vector3i& t = triangles[tri];
  const float w = 1.0f - u - v;
  Eigen::Vector3f color = Eigen::Vector3f::Ones();
  if (!colors.empty()) color = w * colors[t[0]] + u * colors[t[1]] + v * colors[t[2]];
  if (!triangleMaterials.empty()) {
    const int m = triangleMaterials[tri];
    if (m >= 0 && m < static_cast<int>(materials.size())) {
      const Material& mat = materials[m];
      color = color.cwiseProduct(mat.baseColor);
      if (mat.texture >= 0 && mat.texture < static_cast<int>(textures.size()) && !uvs.empty()) {
        const Eigen::Vector2f uv = w * uvs[t[0]] + u * uvs[t[1]] + v * uvs[t[2]];
        color = color.cwiseProduct(textures[mat.texture].sample(uv));
      }
    }
  }
  return color;
}

std::vector<float> triangleAreas(const Mesh& mesh) {
  std::vector<float> areas(mesh.triangles.size(), 0.0f);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    if ((tri.array() < 0).any() || (tri.array() >= static_cast<int>(mesh.positions.size())).any())
      continue;
    const Eigen::Vector3f& a = mesh.positions[static_cast<std::size_t>(tri[0])];
    areas[t] = 0.5f * (mesh.positions[static_cast<std::size_t>(tri[1])] - a)
                          .cross(mesh.positions[static_cast<std::size_t>(tri[2])] - a)
                          .norm();
  }
  return areas;
}

void Mesh::computeVertexNormals() {
  normals.assign(positions.size(), Eigen::Vector3f::Zero());
  for (const auto& t : triangles) {
    const Eigen::Vector3f n =
        (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]);
    for (int k = 0; k < 3; ++k) normals[t[k]] += n;  // |n| = 2 * area: area weighting
  }
  for (auto& n : normals) {
    const float len = n.norm();
    n = len > 0 ? Eigen::Vector3f(n / len) : Eigen::Vector3f::UnitZ();
  }
}

Eigen::Matrix3f fileToZUpRotation(UpAxis fileUp) {
  Eigen::Matrix3f r;
  switch (fileUp) {
    case UpAxis::PosX: r << 0, 0, -1, 0, 1, 0, 1, 0, 0; break;   // -90 about y
    case UpAxis::NegX: r << 0, 0, 1, 0, 1, 0, -1, 0, 0; break;   // +90 about y
    case UpAxis::PosY: r << 1, 0, 0, 0, 0, -1, 0, 1, 0; break;   // +90 about x
    case UpAxis::NegY: r << 1, 0, 0, 0, 0, 1, 0, -1, 0; break;   // -90 about x
    case UpAxis::NegZ: r << 1, 0, 0, 0, -1, 0, 0, 0, -1; break;  // 180 about x
    case UpAxis::PosZ:
    default: r.setIdentity(); break;
  }
  return r;
}

Eigen::Vector3f upAxisVector(UpAxis up) {
  // The rotation takes the up vector to +z, so it is the rotation's last row.
  return fileToZUpRotation(up).row(2).transpose();
}

// Written out as signed permutations (the rotations above, row by row) rather than as matrix
// products: a product turns -0.0 into +0.0, which changed the bytes of every y-up GLB the
// generator writes (the bench split is promised byte-identical for a generator version).
Eigen::Vector3f fileToZUp(const Eigen::Vector3f& p, UpAxis fileUp) {
  switch (fileUp) {
    case UpAxis::PosX: return {-p.z(), p.y(), p.x()};
    case UpAxis::NegX: return {p.z(), p.y(), -p.x()};
    case UpAxis::PosY: return {p.x(), -p.z(), p.y()};
    case UpAxis::NegY: return {p.x(), p.z(), -p.y()};
    case UpAxis::NegZ: return {p.x(), -p.y(), -p.z()};
    case UpAxis::PosZ:
    default: return p;
  }
}

Eigen::Vector3f zUpToFile(const Eigen::Vector3f& p, UpAxis fileUp) {
  switch (fileUp) {
    case UpAxis::PosX: return {p.z(), p.y(), -p.x()};
    case UpAxis::NegX: return {-p.z(), p.y(), p.x()};
    case UpAxis::PosY: return {p.x(), p.z(), -p.y()};
    case UpAxis::NegY: return {p.x(), -p.z(), p.y()};
    case UpAxis::NegZ: return {p.x(), -p.y(), -p.z()};
    case UpAxis::PosZ:
    default: return p;
  }
}

void Mesh::append(const Mesh& part) {
  const int vertexOffset = static_cast<int>(positions.size());
  const int textureOffset = static_cast<int>(textures.size());
  const std::size_t before = positions.size();
  const std::size_t added = part.positions.size();
  // Per-vertex attributes either side lacks are padded, so every array keeps one entry per vertex.
  const auto merge = [&](auto& mine, const auto& theirs, const auto& fill) {
    if (mine.empty() && theirs.empty()) return;
    mine.resize(before, fill);
    if (theirs.size() == added) {
      mine.insert(mine.end(), theirs.begin(), theirs.end());
    } else {
      mine.resize(before + added, fill);
    }
  };
  merge(uvs, part.uvs, Eigen::Vector2f::Zero().eval());
  merge(colors, part.colors, Eigen::Vector3f::Ones().eval());
  merge(normals, part.normals, Eigen::Vector3f::UnitZ().eval());
  positions.insert(positions.end(), part.positions.begin(), part.positions.end());

  if (!part.triangleMaterials.empty() || !part.materials.empty()) {
    // Triangles without a material on this side get a white default when the part brings some.
    if (triangleMaterials.empty() && !triangles.empty()) {
      if (materials.empty()) materials.push_back(Material{"default", Eigen::Vector3f::Ones(), -1});
      triangleMaterials.assign(triangles.size(), 0);
    }
  }
  const int partMaterialOffset = static_cast<int>(materials.size());
  for (Material m : part.materials) {
    if (m.texture >= 0) m.texture += textureOffset;
    materials.push_back(std::move(m));
  }
  textures.insert(textures.end(), part.textures.begin(), part.textures.end());
  for (std::size_t t = 0; t < part.triangles.size(); ++t) {
    triangles.push_back(part.triangles[t] + Eigen::Vector3i::Constant(vertexOffset));
    if (!triangleMaterials.empty() || !part.triangleMaterials.empty()) {
      const int m = t < part.triangleMaterials.size() ? part.triangleMaterials[t] : -1;
      triangleMaterials.push_back(m >= 0 ? m + partMaterialOffset : -1);
    }
  }
}

Mesh Mesh::withoutGeometry() const {
  Mesh out;
  out.materials = materials;
  out.textures = textures;
  out.fileUp = fileUp;
  out.fileUpConfidence = fileUpConfidence;
  out.fileUpDetected = fileUpDetected;
  return out;
}

}  // namespace sagrid
