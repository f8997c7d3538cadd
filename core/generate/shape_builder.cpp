#include "core/generate/shape_builder.h"

#include <algorithm>
#include <cmath>

#include "core/generate/angles.h"

namespace sagrid::gen {

Affine translation(const Vec3& t) {
  Affine a = Affine::Identity();
  a.translation() = t;
  return a;
}
Affine translation(float x, float y, float z) { return translation(Vec3(x, y, z)); }
Affine rotationZ(float r) { return Affine(Eigen::AngleAxisf(r, Vec3::UnitZ())); }
Affine rotationX(float r) { return Affine(Eigen::AngleAxisf(r, Vec3::UnitX())); }
Affine rotationY(float r) { return Affine(Eigen::AngleAxisf(r, Vec3::UnitY())); }

Affine alignZTo(const Vec3& origin, const Vec3& axis) {
  Affine a = translation(origin);
  a.linear() = Eigen::Quaternionf::FromTwoVectors(Vec3::UnitZ(), axis.normalized()).toRotationMatrix();
  return a;
}

ShapeBuilder::ShapeBuilder() = default;

int ShapeBuilder::material(const std::string& name, const Vec3& color, int texture) {
  for (std::size_t i = 0; i < m_mesh.materials.size(); ++i) {
    if (m_mesh.materials[i].name == name) return static_cast<int>(i);
  }
  Material m;
  m.name = name;
  m.baseColor = color.cwiseMax(0.0f).cwiseMin(1.0f);
  m.texture = texture;
  m_mesh.materials.push_back(m);
  return static_cast<int>(m_mesh.materials.size()) - 1;
}

int ShapeBuilder::addTexture(Texture texture) {
  m_mesh.textures.push_back(std::move(texture));
  return static_cast<int>(m_mesh.textures.size()) - 1;
}

int ShapeBuilder::addVertex(const Vec3& p, const Vec2& uv) {
  m_mesh.positions.push_back(p);
  m_mesh.uvs.push_back(uv);
  return static_cast<int>(m_mesh.positions.size()) - 1;
}

void ShapeBuilder::addTriangle(int a, int b, int c, int material) {
  m_mesh.triangles.emplace_back(a, b, c);
  m_mesh.triangleMaterials.push_back(material);
}

void ShapeBuilder::addQuad(int a, int b, int c, int d, int material) {
  addTriangle(a, b, c, material);
  addTriangle(a, c, d, material);
}

void ShapeBuilder::box(const Affine& xf, const Vec3& size, int material, float bevel,
                       int bevelSegments, int subdivisions) {
  const Vec3 h = size * 0.5f;
  const float r = std::clamp(bevel, 0.0f, 0.49f * h.minCoeff());
  const int m = r > 0 ? std::max(1, bevelSegments) : 0;
  const int s = std::max(1, subdivisions);
  const Vec3 inner = h - Vec3::Constant(r);

  // Coordinates along one axis: rounded zone near each end (tan spacing gives even arc steps
  // after the clamp-and-normalise mapping), uniform subdivisions in between.
  auto axisSamples = [&](int axis) {
    std::vector<float> xs;
    for (int k = m; k >= 1; --k) xs.push_back(-(inner[axis] + r * std::tan(0.25f * kPi * k / m)));
    for (int k = 0; k <= s; ++k) xs.push_back(-inner[axis] + 2.0f * inner[axis] * k / s);
    for (int k = 1; k <= m; ++k) xs.push_back(inner[axis] + r * std::tan(0.25f * kPi * k / m));
    return xs;
  };
  const std::vector<float> samples[3] = {axisSamples(0), axisSamples(1), axisSamples(2)};

  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      // (u, v, n) right-handed with n the outward face normal.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (sign < 0) std::swap(u, v);
      const auto& us = samples[u];
      const auto& vs = samples[v];
      const int base = static_cast<int>(m_mesh.positions.size());
      for (std::size_t j = 0; j < vs.size(); ++j) {
        for (std::size_t i = 0; i < us.size(); ++i) {
          Vec3 p;
          p[axis] = sign * h[axis];
          p[u] = us[i];
          p[v] = vs[j];
          if (r > 0) {
            const Vec3 c = p.cwiseMax(-inner).cwiseMin(inner);
            const Vec3 d = p - c;
            if (d.norm() > 0) p = c + r * d.normalized();
          }
          addVertex(xf * p, Vec2(static_cast<float>(i) / (us.size() - 1),
                                 static_cast<float>(j) / (vs.size() - 1)));
        }
      }
      const int nu = static_cast<int>(us.size());
      for (int j = 0; j + 1 < static_cast<int>(vs.size()); ++j) {
        for (int i = 0; i + 1 < nu; ++i) {
          const int a = base + j * nu + i;
          addQuad(a, a + 1, a + 1 + nu, a + nu, material);
        }
      }
    }
  }
}

void ShapeBuilder::boxFromTo(const Vec3& lo, const Vec3& hi, int material, int subdivisions) {
  box(translation(0.5f * (lo + hi)), (hi - lo).cwiseAbs(), material, 0, 0, subdivisions);
}

void ShapeBuilder::lathe(const Affine& xf, const std::vector<Vec2>& profile, int segments,
                         int material) {
  segments = std::max(3, segments);
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const Vec2 a = profile[k], b = profile[k + 1];
    if ((a - b).norm() < 1e-7f) continue;
    const int base = static_cast<int>(m_mesh.positions.size());
    for (int j = 0; j <= segments; ++j) {
      const float t = 2.0f * kPi * j / segments;
      const float c = std::cos(t), s = std::sin(t);
      addVertex(xf * Vec3(a.x() * c, a.x() * s, a.y()), Vec2(float(j) / segments, 0));
      addVertex(xf * Vec3(b.x() * c, b.x() * s, b.y()), Vec2(float(j) / segments, 1));
    }
    for (int j = 0; j < segments; ++j) {
      const int a0 = base + 2 * j, b0 = a0 + 1, a1 = a0 + 2, b1 = a0 + 3;
      // Profile running bottom -> outside -> top gives outward normals with this order.
      if (a.x() > 1e-7f) addTriangle(a0, a1, b1, material);
      if (b.x() > 1e-7f) addTriangle(a0, b1, b0, material);
    }
  }
}

void ShapeBuilder::cylinder(const Affine& xf, float radius, float z0, float z1, int segments,
                            int material) {
  lathe(xf, {{0, z0}, {radius, z0}, {radius, z1}, {0, z1}}, segments, material);
}

void ShapeBuilder::tube(const std::vector<Vec3>& path, float radius, int sides, int material,
                        bool capStart, bool capEnd) {
  if (path.size() < 2) return;
  sides = std::max(3, sides);
  const std::size_t n = path.size();
  std::vector<Vec3> tangents(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 d = path[std::min(k + 1, n - 1)] - path[k == 0 ? 0 : k - 1];
    tangents[k] = d.norm() > 0 ? Vec3(d.normalized()) : Vec3::UnitZ();
  }
  // Parallel transport of the first normal keeps the tube from twisting.
  Vec3 normal = tangents[0].unitOrthogonal();
  std::vector<int> ringStart(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) {
      const Eigen::Quaternionf q = Eigen::Quaternionf::FromTwoVectors(tangents[k - 1], tangents[k]);
      normal = (q * normal).normalized();
      normal = (normal - normal.dot(tangents[k]) * tangents[k]).normalized();
    }
    const Vec3 binormal = tangents[k].cross(normal);
    ringStart[k] = static_cast<int>(m_mesh.positions.size());
    for (int j = 0; j <= sides; ++j) {
      const float t = 2.0f * kPi * j / sides;
      addVertex(path[k] + radius * (std::cos(t) * normal + std::sin(t) * binormal),
                Vec2(float(j) / sides, float(k) / (n - 1)));
    }
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    for (int j = 0; j < sides; ++j) {
      const int a = ringStart[k] + j, b = ringStart[k + 1] + j;
      addQuad(a, a + 1, b + 1, b, material);
    }
  }
  auto cap = [&](std::size_t k, bool atEnd) {
    const int centre = addVertex(path[k]);
    const int first = static_cast<int>(m_mesh.positions.size());
    for (int j = 0; j <= sides; ++j) addVertex(m_mesh.positions[ringStart[k] + j]);
    for (int j = 0; j < sides; ++j) {
      if (atEnd) addTriangle(centre, first + j, first + j + 1, material);
      else addTriangle(centre, first + j + 1, first + j, material);
    }
  };
  if (capStart) cap(0, false);
  if (capEnd) cap(n - 1, true);
}

std::vector<Vec2> ShapeBuilder::sampleRoundedRect(const RoundedRect& rect, int cornerSegments) const {
  const float r = std::clamp(rect.radius, 0.0f, std::min(rect.half.x(), rect.half.y()));
  // Same point count for every radius (zero included) so lofted rings always match up.
  const int k = std::max(1, cornerSegments);
  const Vec2 inner = rect.half - Vec2::Constant(r);
  const Vec2 corners[4] = {{inner.x(), inner.y()}, {-inner.x(), inner.y()},
                           {-inner.x(), -inner.y()}, {inner.x(), -inner.y()}};
  std::vector<Vec2> points;
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i <= k; ++i) {
      const float t = 0.5f * kPi * (c + float(i) / k);
      points.push_back(rect.center + corners[c] + r * Vec2(std::cos(t), std::sin(t)));
    }
  }
  return points;  // counter-clockwise, starting at the +x edge's top end
}

void ShapeBuilder::loft(const Affine& xf, const std::vector<RoundedRect>& rings,
                        int cornerSegments, int material, bool capFirst, bool capLast) {
  if (rings.size() < 2) return;
  std::vector<std::vector<Vec3>> points;
  for (const auto& ring : rings) {
    std::vector<Vec3> ringPoints;
    for (const auto& p : sampleRoundedRect(ring, cornerSegments)) {
      ringPoints.push_back(xf * Vec3(p.x(), p.y(), ring.z));
    }
    points.push_back(std::move(ringPoints));
  }
  const int n = static_cast<int>(points[0].size());
  // Each band gets its own vertices so creases between rings stay sharp.
  for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
    const int a0 = static_cast<int>(m_mesh.positions.size());
    for (int i = 0; i < n; ++i) addVertex(points[k][i]);
    const int b0 = static_cast<int>(m_mesh.positions.size());
    for (int i = 0; i < n; ++i) addVertex(points[k + 1][i]);
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      addQuad(a0 + i, a0 + j, b0 + j, b0 + i, material);
    }
  }
  auto cap = [&](std::size_t k, bool facingUp) {
    const RoundedRect& ring = rings[k];
    const int centre = addVertex(xf * Vec3(ring.center.x(), ring.center.y(), ring.z));
    const int first = static_cast<int>(m_mesh.positions.size());
    for (int i = 0; i < n; ++i) addVertex(points[k][i]);
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      if (facingUp) addTriangle(centre, first + i, first + j, material);
      else addTriangle(centre, first + j, first + i, material);
    }
  };
  // A cap faces away from the loft: the first ring's cap faces down when the loft rises.
  const bool rising = rings.back().z >= rings.front().z;
  if (capFirst) cap(0, !rising);
  if (capLast) cap(rings.size() - 1, rising);
}

void ShapeBuilder::plateWithHole(const Affine& xf, const Vec2& outerHalf, const RoundedRect& hole,
                                 float z0, float z1, int cornerSegments, int material) {
  const std::vector<Vec2> inner = sampleRoundedRect(hole, cornerSegments);
  const int n = static_cast<int>(inner.size());
  const int perCorner = n / 4;
  const Vec2 outerCorners[4] = {{outerHalf.x(), outerHalf.y()}, {-outerHalf.x(), outerHalf.y()},
                                {-outerHalf.x(), -outerHalf.y()}, {outerHalf.x(), -outerHalf.y()}};
  std::vector<Vec2> outer(n);
  for (int i = 0; i < n; ++i) outer[i] = outerCorners[i / perCorner];

  for (int face = 0; face < 2; ++face) {
    const float z = face == 0 ? z1 : z0;
    const int base = static_cast<int>(m_mesh.positions.size());
    for (int i = 0; i < n; ++i) {
      addVertex(xf * Vec3(inner[i].x(), inner[i].y(), z));
      addVertex(xf * Vec3(outer[i].x(), outer[i].y(), z));
    }
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      const int ii = base + 2 * i, oi = ii + 1, ij = base + 2 * j, oj = ij + 1;
      const bool degenerate = (outer[i] - outer[j]).norm() < 1e-9f;
      if (face == 0) {  // top: normal +z
        if (!degenerate) addTriangle(ii, oi, oj, material);
        addTriangle(ii, oj, ij, material);
      } else {
        if (!degenerate) addTriangle(ii, oj, oi, material);
        addTriangle(ii, ij, oj, material);
      }
    }
  }
  // Hole wall faces into the hole; outer walls face out.
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const int a = addVertex(xf * Vec3(inner[i].x(), inner[i].y(), z0));
    const int b = addVertex(xf * Vec3(inner[j].x(), inner[j].y(), z0));
    const int c = addVertex(xf * Vec3(inner[j].x(), inner[j].y(), z1));
    const int d = addVertex(xf * Vec3(inner[i].x(), inner[i].y(), z1));
    addQuad(a, d, c, b, material);
  }
  for (int c = 0; c < 4; ++c) {
    const Vec2 p = outerCorners[c], q = outerCorners[(c + 1) % 4];
    const int a = addVertex(xf * Vec3(p.x(), p.y(), z0));
    const int b = addVertex(xf * Vec3(q.x(), q.y(), z0));
    const int d = addVertex(xf * Vec3(q.x(), q.y(), z1));
    const int e = addVertex(xf * Vec3(p.x(), p.y(), z1));
    addQuad(a, b, d, e, material);  // corners run counter-clockwise: this faces outward
  }
}

void ShapeBuilder::texturedQuad(const Affine& xf, const Vec2& size, int material, int subdivisions) {
  const int s = std::max(1, subdivisions);
  const int base = static_cast<int>(m_mesh.positions.size());
  for (int j = 0; j <= s; ++j) {
    for (int i = 0; i <= s; ++i) {
      const float u = float(i) / s, v = float(j) / s;
      addVertex(xf * Vec3((u - 0.5f) * size.x(), (v - 0.5f) * size.y(), 0), Vec2(u, v));
    }
  }
  for (int j = 0; j < s; ++j) {
    for (int i = 0; i < s; ++i) {
      const int a = base + j * (s + 1) + i;
      addQuad(a, a + 1, a + s + 2, a + s + 1, material);
    }
  }
}

Mesh ShapeBuilder::build() && {
  bool textured = false;
  for (const auto& m : m_mesh.materials) textured = textured || m.texture >= 0;
  if (!textured) m_mesh.uvs.clear();
  m_mesh.computeVertexNormals();
  return std::move(m_mesh);
}

}  // namespace sagrid::gen
