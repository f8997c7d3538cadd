#include "ui/gl/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "core/common/error.h"
#include "ui/gl/framebuffer.h"
#include "ui/gl/gl.h"

namespace sagrid::ui {

namespace {

std::string eglErrorText() {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04x", eglGetError());
  return buffer;
}

// Surfaceless first (Mesa, works without /dev/dri), then the first EGL device (GPU drivers).
EGLDisplay openHeadlessDisplay() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (getPlatformDisplay) {
    EGLDisplay display =
        getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    auto queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (queryDevices && queryDevices(8, devices, &count)) {
      for (EGLint i = 0; i < count; ++i) {
        display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
      }
    }
  }
  throw Error("headless rendering unavailable: no EGL surfaceless platform or EGL device (" +
              eglErrorText() + "); install Mesa's libegl1-mesa / libgl1-mesa-dri");
}

class EglContext final : public GlContext {
 public:
  explicit EglContext(const ContextOptions& options)
      : m_width(options.width),
        m_height(options.height),
        m_start(std::chrono::steady_clock::now()) {
    m_display = openHeadlessDisplay();
    if (!eglBindAPI(EGL_OPENGL_API))
      throw Error("EGL: desktop OpenGL API unavailable (" + eglErrorText() + ")");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    // EGL_KHR_no_config_context + surfaceless_context: no config or surface needed offscreen.
    m_context = eglCreateContext(m_display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (m_context == EGL_NO_CONTEXT) {
      eglTerminate(m_display);
      throw Error("EGL: cannot create an OpenGL 3.3 core context (" + eglErrorText() + ")");
    }
    if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context)) {
      eglDestroyContext(m_display, m_context);
      eglTerminate(m_display);
      throw Error("EGL: cannot make the context current (" + eglErrorText() + ")");
    }
    m_target = std::make_unique<Framebuffer>(m_width, m_height);
  }

  ~EglContext() override {
    m_target.reset();
    eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(m_display, m_context);
    eglTerminate(m_display);
  }

  bool headless() const override { return true; }
  void framebufferSize(int& width, int& height) const override {
    width = m_width, height = m_height;
  }
  void windowSize(int& width, int& height) const override { width = m_width, height = m_height; }
  void setSize(int width, int height) override {
    m_width = width, m_height = height;
    m_target->resize(width, height);
  }
  void setTitle(const std::string&) override {}
  bool shouldClose() const override { return m_closeRequested; }
  void requestClose() override { m_closeRequested = true; }
  void pollEvents(std::vector<InputEvent>&) override {}
  void waitEvents(double) override {}
  void present() override { glFlush(); }
  unsigned screenFramebuffer() const override { return m_target->id(); }
  double timeSeconds() const override {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }
  void setClipboard(const std::string& text) override { m_clipboard = text; }
  std::string clipboard() const override { return m_clipboard; }

 private:
  EGLDisplay m_display = EGL_NO_DISPLAY;
  EGLContext m_context = EGL_NO_CONTEXT;
  int m_width, m_height;
  std::unique_ptr<Framebuffer> m_target;
  bool m_closeRequested = false;
  std::string m_clipboard;
  std::chrono::steady_clock::time_point m_start;
};

}  // namespace

std::unique_ptr<GlContext> createEglContext(const ContextOptions& options) {
  return std::make_unique<EglContext>(options);
}

}  // namespace sagrid::ui
