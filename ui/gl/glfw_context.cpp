#include "ui/gl/glfw_context.h"

#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/common/error.h"
#include "ui/gl/gl.h"

namespace sagrid::ui {

namespace {

class GlfwContext final : public GlContext {
 public:
  explicit GlfwContext(const ContextOptions& options) {
    glfwSetErrorCallback([](int, const char*) {});
    if (!glfwInit()) {
      throw Error(
          "cannot open a window: GLFW could not initialise (no display? set DISPLAY, "
          "use xvfb-run, or use --backend egl)");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    m_window =
        glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!m_window) {
      glfwTerminate();
      throw Error("cannot open a window with OpenGL 3.3 core (driver too old?)");
    }
    glfwMakeContextCurrent(m_window);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(m_window, this);
    glfwSetCursorPosCallback(m_window, [](GLFWwindow* w, double x, double y) {
      self(w)->m_events.push_back(InputEvent::mouseMove(float(x), float(y)));
    });
    glfwSetMouseButtonCallback(m_window, [](GLFWwindow* w, int button, int action, int mods) {
      self(w)->m_events.push_back(InputEvent::mouseButton(button, action == GLFW_PRESS, mods));
    });
    glfwSetScrollCallback(m_window, [](GLFWwindow* w, double dx, double dy) {
      self(w)->m_events.push_back(InputEvent::scroll(float(dx), float(dy)));
    });
    glfwSetKeyCallback(m_window, [](GLFWwindow* w, int key, int, int action, int mods) {
      self(w)->m_events.push_back(InputEvent::keyEvent(key, action != GLFW_RELEASE, mods));
    });
    glfwSetCharCallback(m_window, [](GLFWwindow* w, unsigned codepoint) {
      self(w)->m_events.push_back(InputEvent::character(codepoint));
    });
    glfwSetDropCallback(m_window, [](GLFWwindow* w, int count, const char** paths) {
      std::vector<std::string> list(paths, paths + count);
      self(w)->m_events.push_back(InputEvent::drop(std::move(list)));
    });
  }

  ~GlfwContext() override {
    glfwDestroyWindow(m_window);
    glfwTerminate();
  }

  bool headless() const override { return false; }
  void framebufferSize(int& width, int& height) const override {
    glfwGetFramebufferSize(m_window, &width, &height);
  }
  void windowSize(int& width, int& height) const override {
    glfwGetWindowSize(m_window, &width, &height);
  }
  void setSize(int width, int height) override { glfwSetWindowSize(m_window, width, height); }
  void setTitle(const std::string& title) override { glfwSetWindowTitle(m_window, title.c_str()); }
  bool shouldClose() const override { return glfwWindowShouldClose(m_window); }
  void requestClose() override { glfwSetWindowShouldClose(m_window, GLFW_TRUE); }
  void pollEvents(std::vector<InputEvent>& events) override {
    glfwPollEvents();
    for (auto& e : m_events) events.push_back(std::move(e));
    m_events.clear();
  }
  void waitEvents(double seconds) override { glfwWaitEventsTimeout(seconds); }
  void present() override { glfwSwapBuffers(m_window); }
  unsigned screenFramebuffer() const override { return 0; }
  double timeSeconds() const override { return glfwGetTime(); }
  void setClipboard(const std::string& text) override {
    glfwSetClipboardString(m_window, text.c_str());
  }
  std::string clipboard() const override {
    const char* text = glfwGetClipboardString(m_window);
    return text ? text : "";
  }

 private:
  static GlfwContext* self(GLFWwindow* w) {
    return static_cast<GlfwContext*>(glfwGetWindowUserPointer(w));
  }
  GLFWwindow* m_window = nullptr;
  std::vector<InputEvent> m_events;
};

}  // namespace

std::unique_ptr<GlContext> createGlfwContext(const ContextOptions& options) {
  return std::make_unique<GlfwContext>(options);
}

}  // namespace sagrid::ui
