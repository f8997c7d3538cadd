// The ground grid under the object (on its lowest z, spacing a power of ten of its size, fading
// out at the edge) and short world axes at the origin. Built once per object bounds.
#pragma once

#include <Eigen/Geometry>

#include "ui/gl/gl_objects.h"
#include "ui/render/camera.h"
#include "ui/render/shader_program.h"

namespace sagrid::ui {

class GridRenderer {
 public:
  GridRenderer();
  void build(const Eigen::AlignedBox3f& bounds);
  void draw(const Camera& camera, bool grid, bool axes) const;
  float spacing() const { return m_spacing; }

 private:
  ShaderProgram m_program;
  GLint m_uViewProj, m_uFadeCenter, m_uFadeRadius;
  GlVertexArray m_vao;
  GlBuffer m_buffer;
  GLsizei m_gridVertices = 0, m_axisVertices = 0;
  Eigen::Vector3f m_center = Eigen::Vector3f::Zero();
  float m_radius = 1.0f, m_spacing = 0.1f;
};

}  // namespace sagrid::ui
