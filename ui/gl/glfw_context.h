// GlContext as a GLFW window (OpenGL 3.3 core). Input arrives through GLFW callbacks and is
// queued as InputEvents, so the window and headless runs share one input path.
#pragma once

#include <memory>

#include "ui/gl/gl_context.h"

namespace sagrid::ui {

std::unique_ptr<GlContext> createGlfwContext(const ContextOptions& options);

}  // namespace sagrid::ui
