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

  // Applies the events to ImGui's IO and starts a frame. ImGui (1.86) reads a button's state once
  // per frame, so a press and its release in one batch (a quick click, a touchpad's tap) would
  // never reach a panel: the release and what follows it wait for the next frame.
  void beginFrame(const std::vector<InputEvent>& events, double deltaSeconds);
  bool hasPendingInput() const { return !m_pending.empty(); }  // the next frame has some already
  void render();  // draws ImGui into the bound framebuffer

  bool wantsMouse() const;     // the pointer is over a panel (or a panel drag is active)
  bool wantsKeyboard() const;  // a text field has focus

 private:
  void apply(const InputEvent& e);

  GlContext& m_context;
  std::vector<InputEvent> m_pending;  // held back for the next frame
  std::vector<InputEvent> m_feed;     // this frame's events as fed (reused)
};

}  // namespace sagrid::ui
