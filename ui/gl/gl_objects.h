// Move-only owners of GL object names (buffers, vertex arrays, textures), so renderers release
// what they create and never leak on re-upload.
#pragma once

#include <utility>

#include "ui/gl/gl.h"

namespace sagrid::ui {

template <void (*Delete)(GLsizei, const GLuint*)>
class GlName {
 public:
  GlName() = default;
  ~GlName() { reset(); }
  GlName(GlName&& o) noexcept : m_id(std::exchange(o.m_id, 0)) {}
  GlName& operator=(GlName&& o) noexcept {
    if (this != &o) reset(), m_id = std::exchange(o.m_id, 0);
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;

  GLuint id() const { return m_id; }
  explicit operator bool() const { return m_id != 0; }
  GLuint* create() {
    reset();
    return &m_id;
  }  // pass to glGen*
  void reset() {
    if (m_id) Delete(1, &m_id);
    m_id = 0;
  }

 private:
  GLuint m_id = 0;
};

namespace detail {
inline void deleteBuffers(GLsizei n, const GLuint* ids) { glDeleteBuffers(n, ids); }
inline void deleteVertexArrays(GLsizei n, const GLuint* ids) { glDeleteVertexArrays(n, ids); }
inline void deleteTextures(GLsizei n, const GLuint* ids) { glDeleteTextures(n, ids); }
}  // namespace detail

using GlBuffer = GlName<detail::deleteBuffers>;
using GlVertexArray = GlName<detail::deleteVertexArrays>;
using GlTexture = GlName<detail::deleteTextures>;

inline GlBuffer makeBuffer() {
  GlBuffer b;
  glGenBuffers(1, b.create());
  return b;
}
inline GlVertexArray makeVertexArray() {
  GlVertexArray v;
  glGenVertexArrays(1, v.create());
  return v;
}
inline GlTexture makeTexture() {
  GlTexture t;
  glGenTextures(1, t.create());
  return t;
}

}  // namespace sagrid::ui
