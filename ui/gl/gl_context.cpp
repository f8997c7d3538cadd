#include "ui/gl/gl_context.h"

#include "core/common/error.h"
#include "ui/gl/egl_context.h"
#include "ui/gl/glfw_context.h"

namespace sagrid::ui {

GlBackend parseGlBackend(const std::string& text) {
  if (text == "window" || text == "glfw") return GlBackend::Window;
  if (text == "egl" || text == "headless") return GlBackend::Egl;
  throw InvalidArgument("unknown --backend '" + text + "' (use window or egl)");
}

std::unique_ptr<GlContext> createGlContext(GlBackend backend, const ContextOptions& options) {
  return backend == GlBackend::Egl ? createEglContext(options) : createGlfwContext(options);
}

}  // namespace sagrid::ui
