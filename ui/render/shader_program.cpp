#include "ui/render/shader_program.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "ui/render/shader_sources.h"

namespace sagrid::ui {

namespace {

// GLSL has no #include; shared snippets (colormap.glsl) are spliced in from the embedded files.
std::string expandIncludes(std::string_view file) {
  std::string source(shaderSource(file));
  const std::string directive = "#include \"";
  for (std::size_t at = source.find(directive); at != std::string::npos;
       at = source.find(directive, at)) {
    const std::size_t end = source.find('"', at + directive.size());
    if (end == std::string::npos)
      throw Error("shader " + std::string(file) + ": unterminated #include");
    const std::string name = source.substr(at + directive.size(), end - at - directive.size());
    source.replace(at, end + 1 - at, std::string(shaderSource(name)));
  }
  return source;
}

// The driver's log of a shader or program object (glGetShaderiv/glGetShaderInfoLog or the
// program pair).
template <typename GetParameter, typename GetLog>
std::string infoLog(GLuint object, GetParameter getParameter, GetLog getLog) {
  GLint logLength = 0;
  getParameter(object, GL_INFO_LOG_LENGTH, &logLength);
  std::vector<char> log(static_cast<std::size_t>(std::max(logLength, 1)));
  getLog(object, logLength, nullptr, log.data());
  return log.data();
}

GLuint compile(GLenum stage, std::string_view file) {
  const std::string source = expandIncludes(file);
  GLuint shader = glCreateShader(stage);
  const char* text = source.data();
  const GLint length = static_cast<GLint>(source.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = infoLog(shader, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(shader);
    throw Error("shader " + std::string(file) + " does not compile: " + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(std::string_view vertexFile, std::string_view fragmentFile) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertexFile);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragmentFile);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  m_program = glCreateProgram();
  glAttachShader(m_program, vs);
  glAttachShader(m_program, fs);
  glLinkProgram(m_program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(m_program, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = infoLog(m_program, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(m_program);
    m_program = 0;
    throw Error("shaders " + std::string(vertexFile) + " + " + std::string(fragmentFile) +
                " do not link: " + log);
  }
}

ShaderProgram::~ShaderProgram() {
  if (m_program) glDeleteProgram(m_program);
}

ShaderProgram::ShaderProgram(ShaderProgram&& o) noexcept
    : m_program(std::exchange(o.m_program, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& o) noexcept {
  if (this != &o) {
    if (m_program) glDeleteProgram(m_program);
    m_program = std::exchange(o.m_program, 0);
  }
  return *this;
}

GLint ShaderProgram::uniform(const char* name) const {
  return glGetUniformLocation(m_program, name);
}

}  // namespace sagrid::ui
