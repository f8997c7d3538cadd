// An offscreen render target (RGBA8 colour + 24-bit depth / 8-bit stencil renderbuffers) and
// pixel readback. Headless drawing goes here; screenshots read back from any framebuffer.
#pragma once

#include "ui/gl/image.h"

namespace sagrid::ui {

class Framebuffer {
 public:
  Framebuffer() = default;
  Framebuffer(int width, int height);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  void resize(int width, int height);  // keeps the GL objects when the size is unchanged
  unsigned id() const { return m_fbo; }
  int width() const { return m_width; }
  int height() const { return m_height; }

 private:
  void release();
  unsigned m_fbo = 0, m_color = 0, m_depth = 0;
  int m_width = 0, m_height = 0;
};

// Reads the colour of framebuffer `fbo` (0 = the window's back buffer), rows top to bottom.
RgbaImage readFramebuffer(unsigned fbo, int width, int height);

}  // namespace sagrid::ui
