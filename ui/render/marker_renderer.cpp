#include "ui/render/marker_renderer.h"

#include <cmath>

namespace sagrid::ui {

namespace {
constexpr int kRings = 10, kSegments = 16;
constexpr std::size_t kFloatsPerMarker = 8;
}  // namespace

MarkerRenderer::MarkerRenderer() : m_program("marker.vert", "marker.frag") {
  m_uViewProj = m_program.uniform("uViewProj");
  m_uEye = m_program.uniform("uEye");
  m_uForward = m_program.uniform("uForward");
  m_uWorldPerPixel = m_program.uniform("uWorldPerPixelPerDepth");
  m_uViewDir = m_program.uniform("uViewDir");
  m_uAlpha = m_program.uniform("uAlpha");

  std::vector<float> vertices;
  for (int r = 0; r <= kRings; ++r) {
    const float theta = float(M_PI) * float(r) / kRings;
    for (int s = 0; s <= kSegments; ++s) {
      const float phi = 2.0f * float(M_PI) * float(s) / kSegments;
      vertices.insert(vertices.end(), {std::sin(theta) * std::cos(phi),
                                       std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  }
  std::vector<unsigned> indices;
  for (int r = 0; r < kRings; ++r) {
    for (int s = 0; s < kSegments; ++s) {
      const unsigned a = unsigned(r * (kSegments + 1) + s), b = a + kSegments + 1;
      indices.insert(indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  m_indexCount = static_cast<GLsizei>(indices.size());
  m_vao = makeVertexArray();
  m_sphere = makeBuffer();
  m_sphereIndices = makeBuffer();
  m_instances = makeBuffer();
  glBindVertexArray(m_vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, m_sphere.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_sphereIndices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(unsigned)),
               indices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, m_instances.id());
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, kFloatsPerMarker * sizeof(float), nullptr);
  glVertexAttribDivisor(1, 1);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, kFloatsPerMarker * sizeof(float),
                        reinterpret_cast<void*>(4 * sizeof(float)));
  glVertexAttribDivisor(2, 1);
  glBindVertexArray(0);
}

void MarkerRenderer::upload(const std::vector<MarkerInstance>& markers) {
  m_staging.clear();
  for (const auto& m : markers) {
    m_staging.insert(m_staging.end(),
                     {m.position.x(), m.position.y(), m.position.z(), m.radiusPixels, m.color[0],
                      m.color[1], m.color[2], m.color[3]});
  }
  glBindBuffer(GL_ARRAY_BUFFER, m_instances.id());
  if (markers.size() > m_capacity) {
    m_capacity = std::max<std::size_t>(markers.size(), 16);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m_capacity * kFloatsPerMarker * sizeof(float)),
                 nullptr, GL_DYNAMIC_DRAW);
  }
  if (!m_staging.empty()) {
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(m_staging.size() * sizeof(float)),
                    m_staging.data());
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  m_count = static_cast<GLsizei>(markers.size());
}

void MarkerRenderer::draw(const Camera& camera) const {
  if (m_count == 0) return;
  m_program.use();
  const Eigen::Vector3f forward = (camera.target() - camera.eye()).normalized();
  setUniform(m_uViewProj, camera.viewProjection());
  setUniform(m_uEye, camera.eye());
  setUniform(m_uForward, forward);
  setUniform(m_uViewDir, forward);
  setUniform(m_uWorldPerPixel, 2.0f * std::tan(0.5f * camera.verticalFovRadians()) /
                                   float(std::max(camera.height(), 1)));
  glBindVertexArray(m_vao.id());
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  // Hidden parts first, faint and without depth writes; then the visible markers.
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  setUniform(m_uAlpha, 0.35f);
  glDrawElementsInstanced(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr, m_count);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  setUniform(m_uAlpha, 1.0f);
  glDrawElementsInstanced(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr, m_count);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
}

}  // namespace sagrid::ui
