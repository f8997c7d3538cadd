// Draws a Mesh lit, with per-vertex colour and per-material base colour/texture albedo, and an
// optional wireframe overlay. Geometry is uploaded once per mesh (triangles grouped by material).
#pragma once

#include <vector>

#include "ui/gl/gl_objects.h"
#include "ui/render/camera.h"
#include "ui/render/shader_program.h"

namespace sagrid {
struct Mesh;
}

namespace sagrid::ui {

class MeshRenderer {
 public:
  MeshRenderer();
  void upload(const Mesh& mesh);
  bool hasMesh() const { return m_indexCount > 0; }
  GLsizei indexCount() const { return m_indexCount; }  // three per uploaded triangle
  enum class Colouring {
    Modelled,    // materials, textures and vertex colours
    Plain,       // one light grey (ViewSettings::plainShading)
    ByMaterial,  // each material in a colour of its own (ViewSettings::materialColours)
  };
  void draw(const Camera& camera, bool wireframe, Colouring colouring = Colouring::Modelled) const;

 private:
  struct Range {
    GLsizei first = 0, count = 0;
    Eigen::Vector3f baseColor = Eigen::Vector3f::Ones();
    int texture = -1;
    int material = -1;
  };
  ShaderProgram m_program;
  GLint m_uViewProj, m_uEye, m_uBaseColor, m_uHasTexture, m_uTexture, m_uFlatColor, m_uPlain, m_uAlpha;
  GlVertexArray m_vao;
  GlBuffer m_vertices, m_indices;
  std::vector<GlTexture> m_textures;
  std::vector<Range> m_ranges;
  GLsizei m_indexCount = 0;
};

}  // namespace sagrid::ui
