// Dear ImGui on our GlContext: the OpenGL3 renderer backend, and input fed from InputEvents
// (instead of ImGui's GLFW backend) so the window and headless scripted runs behave the same.
#pragma once

#include <vector>

#include "ui/gl/gl_context.h"

namespace sagrid::ui {

class ImGuiLayer {
 public:
  explicit ImGuiLayer(GlContext& context);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Applies the events to ImGui's IO and starts a frame.
  void beginFrame(const std::vector<InputEvent>& events, double deltaSeconds);
  void render();  // draws ImGui into the bound framebuffer

  bool wantsMouse() const;     // the pointer is over a panel (or a panel drag is active)
  bool wantsKeyboard() const;  // a text field has focus

 private:
  GlContext& m_context;
};

}  // namespace sagrid::ui
