#include "ui/render/mesh_renderer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/mesh/mesh.h"

namespace sagrid::ui {

namespace {
struct Vertex {
  float position[3];
  float normal[3];
  float color[3];
  float uv[2];
};

// Well-separated colours for material indices (hues a golden angle apart); -1, no material, grey.
Eigen::Vector3f materialColour(int material) {
  if (material < 0) return Eigen::Vector3f::Constant(0.6f);
  const float hue = std::fmod(0.13f + 0.618034f * float(material), 1.0f) * 6.0f;
  const float x = 1.0f - std::fabs(std::fmod(hue, 2.0f) - 1.0f);
  Eigen::Vector3f rgb;
  switch (int(hue)) {
    case 0: rgb = {1, x, 0}; break;
    case 1: rgb = {x, 1, 0}; break;
    case 2: rgb = {0, 1, x}; break;
    case 3: rgb = {0, x, 1}; break;
    case 4: rgb = {x, 0, 1}; break;
    default: rgb = {1, 0, x}; break;
  }
  return 0.25f * Eigen::Vector3f::Ones() + 0.7f * rgb;  // bright, not saturated to white
}
}  // namespace

MeshRenderer::MeshRenderer() : m_program("mesh.vert", "mesh.frag") {
  m_uViewProj = m_program.uniform("uViewProj");
  m_uEye = m_program.uniform("uEye");
  m_uBaseColor = m_program.uniform("uBaseColor");
  m_uHasTexture = m_program.uniform("uHasTexture");
  m_uTexture = m_program.uniform("uTexture");
  m_uFlatColor = m_program.uniform("uFlatColor");
  m_uAlpha = m_program.uniform("uAlpha");
  m_uPlain = m_program.uniform("uPlain");
  m_uContrast = m_program.uniform("uContrast");
}

void MeshRenderer::upload(const Mesh& mesh) {
  std::vector<Vertex> vertices(mesh.positions.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    Vertex& v = vertices[i];
    const auto& p = mesh.positions[i];
    const Eigen::Vector3f n = i < mesh.normals.size() ? mesh.normals[i] : Eigen::Vector3f::Zero();
    const Eigen::Vector3f c = i < mesh.colors.size() ? mesh.colors[i] : Eigen::Vector3f::Ones();
    const Eigen::Vector2f uv = i < mesh.uvs.size() ? mesh.uvs[i] : Eigen::Vector2f::Zero();
    for (int k = 0; k < 3; ++k) v.position[k] = p[k], v.normal[k] = n[k], v.color[k] = c[k];
    v.uv[0] = uv[0], v.uv[1] = uv[1];
  }
  // Group triangles by material so each material is one draw call.
  std::vector<int> order(mesh.triangles.size());
  std::iota(order.begin(), order.end(), 0);
  auto materialOf = [&](int t) {
    return t < static_cast<int>(mesh.triangleMaterials.size())
               ? mesh.triangleMaterials[std::size_t(t)]
               : -1;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return materialOf(a) < materialOf(b); });
  std::vector<unsigned> indices;
  indices.reserve(order.size() * 3);
  m_ranges.clear();
  int currentMaterial = -2;
  for (int t : order) {
    const int material = materialOf(t);
    if (material != currentMaterial) {
      currentMaterial = material;
      Range range;
      range.first = static_cast<GLsizei>(indices.size());
      range.material = material;
      if (material >= 0 && material < static_cast<int>(mesh.materials.size())) {
        range.baseColor = mesh.materials[std::size_t(material)].baseColor;
        range.texture = mesh.materials[std::size_t(material)].texture;
      }
      m_ranges.push_back(range);
    }
    for (int k = 0; k < 3; ++k)
      indices.push_back(static_cast<unsigned>(mesh.triangles[std::size_t(t)][k]));
    m_ranges.back().count += 3;
  }

  m_vao = makeVertexArray();
  m_vertices = makeBuffer();
  m_indices = makeBuffer();
  glBindVertexArray(m_vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, m_vertices.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(unsigned)),
               indices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, color)));
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, uv)));
  glBindVertexArray(0);
  m_indexCount = static_cast<GLsizei>(indices.size());

  m_textures.clear();
  m_textureRanges.clear();
  for (const auto& texture : mesh.textures) {
    m_textureRanges.push_back(luminanceRange(texture));
    GlTexture t = makeTexture();
    glBindTexture(GL_TEXTURE_2D, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Rows are stored top to bottom, so the first uploaded row (GL t=0) is the top: mesh.frag
    // samples at 1 - v to keep v=0 at the bottom as the Mesh convention says.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, texture.width, texture.height, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texture.rgba.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    m_textures.push_back(std::move(t));
  }
}

void MeshRenderer::draw(const Camera& camera, bool wireframe, SurfaceColouring colouring) const {
  if (!m_indexCount) return;
  m_program.use();
  setUniform(m_uViewProj, camera.viewProjection());
  setUniform(m_uEye, camera.eye());
  setUniform(m_uTexture, 0);
  setUniform(m_uAlpha, 1.0f);
  setUniform(m_uFlatColor, 0);
  // mesh.frag's uPlain numbers the colourings as SurfaceColouring does.
  static_assert(int(SurfaceColouring::Modelled) == 0 && int(SurfaceColouring::PlainGrey) == 1 &&
                int(SurfaceColouring::ByMaterial) == 2 && int(SurfaceColouring::TextureContrast) == 3);
  setUniform(m_uPlain, int(colouring));
  glBindVertexArray(m_vao.id());
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);  // keeps the wireframe overlay and markers on top
  for (const Range& r : m_ranges) {
    const bool textured = r.texture >= 0 && r.texture < static_cast<int>(m_textures.size());
    setUniform(m_uBaseColor, colouring == SurfaceColouring::ByMaterial ? materialColour(r.material) : r.baseColor);
    setUniform(m_uHasTexture, textured ? 1 : 0);
    if (textured) {
      const LuminanceRange& range = m_textureRanges[std::size_t(r.texture)];
      setUniform(m_uContrast, Eigen::Vector2f(range.low, range.high));
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, m_textures[std::size_t(r.texture)].id());
    }
    glDrawElements(GL_TRIANGLES, r.count, GL_UNSIGNED_INT,
                   reinterpret_cast<void*>(std::size_t(r.first) * sizeof(unsigned)));
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  if (wireframe) {
    setUniform(m_uFlatColor, 1);
    setUniform(m_uBaseColor, Eigen::Vector3f(0.08f, 0.09f, 0.11f));
    setUniform(m_uAlpha, 0.55f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_BLEND);
  }
  glBindVertexArray(0);
}

}  // namespace sagrid::ui
