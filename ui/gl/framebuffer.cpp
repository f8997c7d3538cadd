#include "ui/gl/framebuffer.h"

#include <cstring>

#include "core/common/error.h"
#include "ui/gl/gl.h"

namespace sagrid::ui {

Framebuffer::Framebuffer(int width, int height) { resize(width, height); }

Framebuffer::~Framebuffer() { release(); }

void Framebuffer::release() {
  if (m_fbo) glDeleteFramebuffers(1, &m_fbo);
  if (m_color) glDeleteRenderbuffers(1, &m_color);
  if (m_depth) glDeleteRenderbuffers(1, &m_depth);
  m_fbo = m_color = m_depth = 0;
}

void Framebuffer::resize(int width, int height) {
  if (m_fbo && width == m_width && height == m_height) return;
  release();
  m_width = width;
  m_height = height;
  glGenFramebuffers(1, &m_fbo);
  glGenRenderbuffers(1, &m_color);
  glGenRenderbuffers(1, &m_depth);
  glBindRenderbuffer(GL_RENDERBUFFER, m_color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, m_depth);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("offscreen framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                " is incomplete (GL status " + std::to_string(status) + ")");
  }
}

RgbaImage readFramebuffer(unsigned fbo, int width, int height) {
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(std::size_t(width) * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  if (fbo == 0) glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // GL rows go bottom to top; PNG rows top to bottom.
  const std::size_t row = std::size_t(width) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < height / 2; ++y) {
    std::uint8_t* a = image.pixels.data() + y * row;
    std::uint8_t* b = image.pixels.data() + (height - 1 - y) * row;
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;  // opaque PNG
  return image;
}

}  // namespace sagrid::ui
