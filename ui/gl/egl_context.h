// GlContext headless through EGL (Mesa surfaceless platform, or an EGL device): OpenGL 3.3+ core
// with no display, drawing into an offscreen Framebuffer. Input comes only from scripts
// (GlContext::pollEvents returns nothing; tests hand events to the app directly).
#pragma once

#include <memory>

#include "ui/gl/gl_context.h"

namespace sagrid::ui {

std::unique_ptr<GlContext> createEglContext(const ContextOptions& options);

}  // namespace sagrid::ui
