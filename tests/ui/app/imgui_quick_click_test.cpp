// A quick click on a panel (press and release in one frame's events: a fast mouse, a touchpad's
// tap, a scripted session) presses the panel's button: the release waits for the next frame
// instead of undoing the press before ImGui saw it (seen curating in the window: the category
// list and the points list ignored clicks).
#include "ui/app/imgui_layer.h"

#include <gtest/gtest.h>

#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "ui/gl/gl_context.h"

namespace sagrid::ui {
namespace {

// One frame with a window holding one button at its top-left; true if the button was pressed.
bool frameWithButton(ImGuiLayer& layer, const std::vector<InputEvent>& events) {
  layer.beginFrame(events, 1.0 / 60.0);
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(200, 100));
  ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoDecoration);
  const bool pressed = ImGui::Button("Take", ImVec2(120, 40));
  ImGui::End();
  layer.render();
  return pressed;
}

TEST(ImGuiQuickClick, APressAndReleaseInOneFramePressTheButton) {
  ContextOptions options;
  options.width = 320;
  options.height = 240;
  const auto gl = createGlContext(GlBackend::Egl, options);
  ImGuiLayer layer(*gl);
  EXPECT_FALSE(frameWithButton(layer, {}));  // the window exists from here on
  const float x = 40, y = 25;                 // on the button
  EXPECT_FALSE(frameWithButton(layer, {InputEvent::mouseMove(x, y),
                                       InputEvent::mouseButton(GLFW_MOUSE_BUTTON_LEFT, true),
                                       InputEvent::mouseButton(GLFW_MOUSE_BUTTON_LEFT, false)}));
  EXPECT_TRUE(layer.hasPendingInput());
  EXPECT_TRUE(frameWithButton(layer, {}));  // the release, one frame later
  EXPECT_FALSE(layer.hasPendingInput());
  EXPECT_FALSE(frameWithButton(layer, {}));
}

}  // namespace
}  // namespace sagrid::ui
