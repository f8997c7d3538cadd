// Draws a Mesh lit, with per-vertex colour and per-material base colour/texture albedo, and an
// optional wireframe overlay. Geometry is uploaded once per mesh (triangles grouped by material).
#pragma once

#include <vector>

#include "ui/gl/gl_objects.h"
#include "ui/render/camera.h"
#include "ui/render/shader_program.h"
#include "ui/render/texture_contrast.h"
#include "ui/render/view_settings.h"

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
  void draw(const Camera& camera, bool wireframe,
            SurfaceColouring colouring = SurfaceColouring::Modelled) const;

 private:
  struct Range {
    GLsizei first = 0, count = 0;
    Eigen::Vector3f baseColor = Eigen::Vector3f::Ones();
    int texture = -1;
    int material = -1;
  };
  ShaderProgram m_program;
  GLint m_uViewProj, m_uEye, m_uBaseColor, m_uHasTexture, m_uTexture, m_uFlatColor, m_uPlain, m_uAlpha,
      m_uContrast;
  GlVertexArray m_vao;
  GlBuffer m_vertices, m_indices;
  std::vector<GlTexture> m_textures;
  std::vector<LuminanceRange> m_textureRanges;  // per texture, for SurfaceColouring::TextureContrast
  std::vector<Range> m_ranges;
  GLsizei m_indexCount = 0;
};

}  // namespace sagrid::ui
