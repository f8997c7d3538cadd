#include "ui/render/grid_renderer.h"

#include <cmath>
#include <vector>

namespace sagrid::ui {

namespace {
struct LineVertex {
  float position[3];
  float color[4];
};
void addLine(std::vector<LineVertex>& out, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
             const Eigen::Vector4f& c) {
  out.push_back({{a.x(), a.y(), a.z()}, {c[0], c[1], c[2], c[3]}});
  out.push_back({{b.x(), b.y(), b.z()}, {c[0], c[1], c[2], c[3]}});
}
}  // namespace

GridRenderer::GridRenderer() : m_program("lines.vert", "lines.frag") {
  m_uViewProj = m_program.uniform("uViewProj");
  m_uFadeCenter = m_program.uniform("uFadeCenter");
  m_uFadeRadius = m_program.uniform("uFadeRadius");
}

void GridRenderer::build(const Eigen::AlignedBox3f& bounds) {
  const Eigen::Vector3f size = bounds.sizes();
  const float extent = std::max({size.x(), size.y(), size.z(), 1e-6f});
  m_spacing = std::pow(10.0f, std::floor(std::log10(extent / 2.0f)));
  m_center = bounds.center();
  m_center.z() = bounds.min().z();
  m_radius = 1.5f * extent;
  const int half = static_cast<int>(std::ceil(m_radius / m_spacing));
  const float cx = std::round(m_center.x() / m_spacing) * m_spacing;
  const float cy = std::round(m_center.y() / m_spacing) * m_spacing;
  const float z = m_center.z();
  std::vector<LineVertex> lines;
  for (int i = -half; i <= half; ++i) {
    const bool major = (static_cast<int>(std::lround(cx / m_spacing)) + i) % 10 == 0;
    const Eigen::Vector4f c = major ? Eigen::Vector4f(0.55f, 0.57f, 0.62f, 0.7f)
                                    : Eigen::Vector4f(0.42f, 0.44f, 0.48f, 0.45f);
    const float x = cx + i * m_spacing, y = cy + i * m_spacing;
    addLine(lines, {x, cy - half * m_spacing, z}, {x, cy + half * m_spacing, z}, c);
    addLine(lines, {cx - half * m_spacing, y, z}, {cx + half * m_spacing, y, z}, c);
  }
  m_gridVertices = static_cast<GLsizei>(lines.size());
  const float axis = 0.35f * extent;
  addLine(lines, {0, 0, 0}, {axis, 0, 0}, {0.90f, 0.25f, 0.25f, 1.0f});
  addLine(lines, {0, 0, 0}, {0, axis, 0}, {0.35f, 0.80f, 0.30f, 1.0f});
  addLine(lines, {0, 0, 0}, {0, 0, axis}, {0.30f, 0.50f, 0.95f, 1.0f});
  m_axisVertices = 6;

  m_vao = makeVertexArray();
  m_buffer = makeBuffer();
  glBindVertexArray(m_vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, m_buffer.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(lines.size() * sizeof(LineVertex)), lines.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                        reinterpret_cast<void*>(offsetof(LineVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                        reinterpret_cast<void*>(offsetof(LineVertex, color)));
  glBindVertexArray(0);
}

void GridRenderer::draw(const Camera& camera, bool grid, bool axes) const {
  if (!m_vao || (!grid && !axes)) return;
  m_program.use();
  setUniform(m_uViewProj, camera.viewProjection());
  setUniform(m_uFadeCenter, m_center);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindVertexArray(m_vao.id());
  if (grid) {
    setUniform(m_uFadeRadius, m_radius);
    glDepthMask(GL_FALSE);
    glDrawArrays(GL_LINES, 0, m_gridVertices);
    glDepthMask(GL_TRUE);
  }
  if (axes) {
    setUniform(m_uFadeRadius, 1e30f);
    glDrawArrays(GL_LINES, m_gridVertices, m_axisVertices);
  }
  glBindVertexArray(0);
  glDisable(GL_BLEND);
}

}  // namespace sagrid::ui
