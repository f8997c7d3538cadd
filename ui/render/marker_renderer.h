// Affordance point markers: instanced spheres of constant screen size, coloured by type. Points
// hidden behind the mesh are drawn again faintly, so the curator sees every point. Instances
// change only when the points (or a drag preview) change; their vectors keep their capacity.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "ui/gl/gl_objects.h"
#include "ui/render/camera.h"
#include "ui/render/shader_program.h"

namespace sagrid::ui {

struct MarkerInstance {
  Eigen::Vector3f position;  // z-up world
  float radiusPixels = 8.0f;
  Eigen::Vector4f color;
};

class MarkerRenderer {
 public:
  MarkerRenderer();
  void upload(const std::vector<MarkerInstance>& markers);
  void draw(const Camera& camera) const;

 private:
  ShaderProgram m_program;
  GLint m_uViewProj, m_uEye, m_uForward, m_uWorldPerPixel, m_uViewDir, m_uAlpha;
  GlVertexArray m_vao;
  GlBuffer m_sphere, m_sphereIndices, m_instances;
  GLsizei m_indexCount = 0;
  GLsizei m_count = 0;
  std::size_t m_capacity = 0;
  std::vector<float> m_staging;
};

}  // namespace sagrid::ui
