// The GL context interface: everything the application needs from "a place to draw", with two
// implementations chosen at run time (as Polyscope does): a GLFW window, and EGL headless
// (surfaceless, no display) for tests, `sagrid render` and benchmarks. Drawing always goes to
// an offscreen Framebuffer first, so both paths render the same pixels.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ui/gl/input_event.h"

namespace sagrid::ui {

enum class GlBackend { Window, Egl };
GlBackend parseGlBackend(const std::string& text);  // "window" | "glfw" | "egl"

struct ContextOptions {
  int width = 1280;
  int height = 800;
  std::string title = "SAGrid";
  bool visible = true;  // window only
};

class GlContext {
 public:
  virtual ~GlContext() = default;

  virtual bool headless() const = 0;
  // Size of the drawable in pixels (window framebuffer, or the headless target size).
  virtual void framebufferSize(int& width, int& height) const = 0;
  // Size in window coordinates (mouse events use these; differs from pixels on HiDPI).
  virtual void windowSize(int& width, int& height) const = 0;
  virtual void setSize(int width, int height) = 0;
  virtual void setTitle(const std::string& title) = 0;
  virtual bool shouldClose() const = 0;
  virtual void requestClose() = 0;
  // Appends the input that arrived since the last call (window: from GLFW's callbacks).
  virtual void pollEvents(std::vector<InputEvent>& events) = 0;
  // Blocks until input arrives or `seconds` pass (window); returns at once headless.
  virtual void waitEvents(double seconds) = 0;
  // Shows the frame drawn into the default framebuffer (window); no-op headless.
  virtual void present() = 0;
  // Id of the framebuffer that reaches the screen (0 for the window; the offscreen one headless).
  virtual unsigned screenFramebuffer() const = 0;
  virtual double timeSeconds() const = 0;
  // Clipboard for ImGui; headless keeps a private string.
  virtual void setClipboard(const std::string& text) = 0;
  virtual std::string clipboard() const = 0;
};

// Throws sagrid::Error with what failed (no display, no EGL device, GL too old).
std::unique_ptr<GlContext> createGlContext(GlBackend backend, const ContextOptions& options);

}  // namespace sagrid::ui
