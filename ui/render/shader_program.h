// A linked GLSL program built from the embedded shaders/ sources, with cached uniform locations
// (looked up once at build time, so setting uniforms in the frame loop does no string work).
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>

#include "ui/gl/gl.h"

namespace sagrid::ui {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // Compiles shaders/<vertexFile> and shaders/<fragmentFile>; throws sagrid::Error with the GL
  // info log on failure.
  ShaderProgram(std::string_view vertexFile, std::string_view fragmentFile);
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& o) noexcept;
  ShaderProgram& operator=(ShaderProgram&& o) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return m_program; }
  void use() const { glUseProgram(m_program); }
  GLint uniform(const char* name) const;  // -1 if absent (GL ignores sets to -1)

 private:
  GLuint m_program = 0;
};

inline void setUniform(GLint loc, const Eigen::Matrix4f& m) {
  glUniformMatrix4fv(loc, 1, GL_FALSE, m.data());
}
inline void setUniform(GLint loc, const Eigen::Vector2f& v) { glUniform2f(loc, v.x(), v.y()); }
inline void setUniform(GLint loc, const Eigen::Vector3f& v) {
  glUniform3f(loc, v.x(), v.y(), v.z());
}
inline void setUniform(GLint loc, const Eigen::Vector4f& v) {
  glUniform4f(loc, v.x(), v.y(), v.z(), v.w());
}
inline void setUniform(GLint loc, float f) { glUniform1f(loc, f); }
inline void setUniform(GLint loc, int i) { glUniform1i(loc, i); }

}  // namespace sagrid::ui
