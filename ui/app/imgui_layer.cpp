#include "ui/app/imgui_layer.h"

#include <filesystem>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "core/common/error.h"

namespace sagrid::ui {

namespace {

const char* getClipboard(void* user) {
  static std::string text;
  text = static_cast<GlContext*>(user)->clipboard();
  return text.c_str();
}

void setClipboard(void* user, const char* text) {
  static_cast<GlContext*>(user)->setClipboard(text);
}

void applyStyle() {
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 6.0f;
  style.FrameRounding = 4.0f;
  style.GrabRounding = 4.0f;
  style.WindowBorderSize = 0.0f;
  style.WindowPadding = ImVec2(10, 8);
  style.ItemSpacing = ImVec2(8, 6);
  ImVec4* c = style.Colors;
  c[ImGuiCol_WindowBg] = ImVec4(0.11f, 0.12f, 0.14f, 0.94f);
  c[ImGuiCol_TitleBg] = ImVec4(0.14f, 0.16f, 0.19f, 1.0f);
  c[ImGuiCol_TitleBgActive] = ImVec4(0.18f, 0.22f, 0.28f, 1.0f);
  c[ImGuiCol_Header] = ImVec4(0.24f, 0.36f, 0.52f, 0.55f);
  c[ImGuiCol_HeaderHovered] = ImVec4(0.28f, 0.44f, 0.64f, 0.80f);
  c[ImGuiCol_Button] = ImVec4(0.22f, 0.30f, 0.42f, 0.80f);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.28f, 0.40f, 0.58f, 1.0f);
  c[ImGuiCol_FrameBg] = ImVec4(0.18f, 0.20f, 0.24f, 1.0f);
}

}  // namespace

ImGuiLayer::ImGuiLayer(GlContext& context) : m_context(context) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // layout is ours, not a file dropped in the working directory
  io.ClipboardUserData = &m_context;
  io.GetClipboardTextFn = getClipboard;
  io.SetClipboardTextFn = setClipboard;
  io.BackendPlatformName = "sagrid";
  const int map[][2] = {{ImGuiKey_Tab, GLFW_KEY_TAB},
                        {ImGuiKey_LeftArrow, GLFW_KEY_LEFT},
                        {ImGuiKey_RightArrow, GLFW_KEY_RIGHT},
                        {ImGuiKey_UpArrow, GLFW_KEY_UP},
                        {ImGuiKey_DownArrow, GLFW_KEY_DOWN},
                        {ImGuiKey_PageUp, GLFW_KEY_PAGE_UP},
                        {ImGuiKey_PageDown, GLFW_KEY_PAGE_DOWN},
                        {ImGuiKey_Home, GLFW_KEY_HOME},
                        {ImGuiKey_End, GLFW_KEY_END},
                        {ImGuiKey_Insert, GLFW_KEY_INSERT},
                        {ImGuiKey_Delete, GLFW_KEY_DELETE},
                        {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE},
                        {ImGuiKey_Space, GLFW_KEY_SPACE},
                        {ImGuiKey_Enter, GLFW_KEY_ENTER},
                        {ImGuiKey_Escape, GLFW_KEY_ESCAPE},
                        {ImGuiKey_KeyPadEnter, GLFW_KEY_KP_ENTER},
                        {ImGuiKey_A, GLFW_KEY_A},
                        {ImGuiKey_C, GLFW_KEY_C},
                        {ImGuiKey_V, GLFW_KEY_V},
                        {ImGuiKey_X, GLFW_KEY_X},
                        {ImGuiKey_Y, GLFW_KEY_Y},
                        {ImGuiKey_Z, GLFW_KEY_Z}};
  for (const auto& [imguiKey, glfwKey] : map) io.KeyMap[imguiKey] = glfwKey;

  // DejaVu Sans reads better than the built-in bitmap font; fall back to it when absent.
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  std::error_code ec;
  if (std::filesystem::exists(font, ec)) io.Fonts->AddFontFromFileTTF(font, 15.0f);
  applyStyle();
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui::DestroyContext();
    throw Error("Dear ImGui: the OpenGL 3 renderer could not start");
  }
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::beginFrame(const std::vector<InputEvent>& events, double deltaSeconds) {
  ImGuiIO& io = ImGui::GetIO();
  int w = 0, h = 0, fw = 0, fh = 0;
  m_context.windowSize(w, h);
  m_context.framebufferSize(fw, fh);
  io.DisplaySize = ImVec2(float(w), float(h));
  if (w > 0 && h > 0)
    io.DisplayFramebufferScale = ImVec2(float(fw) / float(w), float(fh) / float(h));
  io.DeltaTime = deltaSeconds > 0 ? float(deltaSeconds) : 1.0f / 60.0f;
  // The held-back events first, then this frame's; one buffer kept across frames (no allocation
  // per frame once it has grown).
  m_feed.swap(m_pending);
  m_pending.clear();
  m_feed.insert(m_feed.end(), events.begin(), events.end());
  bool pressedThisFrame[5] = {};
  for (std::size_t i = 0; i < m_feed.size(); ++i) {
    const InputEvent& e = m_feed[i];
    if (e.kind == InputEvent::Kind::MouseButton && e.button >= 0 && e.button < 5) {
      if (!e.pressed && pressedThisFrame[e.button]) {
        m_pending.assign(m_feed.begin() + std::ptrdiff_t(i), m_feed.end());
        break;
      }
      if (e.pressed) pressedThisFrame[e.button] = true;
    }
    apply(e);
  }
  m_feed.clear();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::apply(const InputEvent& e) {
  ImGuiIO& io = ImGui::GetIO();
  switch (e.kind) {
    case InputEvent::Kind::MouseMove:
      io.MousePos = ImVec2(e.x, e.y);
      break;
    case InputEvent::Kind::MouseButton:
      if (e.button >= 0 && e.button < 5) io.MouseDown[e.button] = e.pressed;
      break;
    case InputEvent::Kind::Scroll:
      io.MouseWheelH += e.x;
      io.MouseWheel += e.y;
      break;
    case InputEvent::Kind::Key:
      if (e.key >= 0 && e.key < 512) io.KeysDown[e.key] = e.pressed;
      io.KeyCtrl = (e.mods & GLFW_MOD_CONTROL) != 0;
      io.KeyShift = (e.mods & GLFW_MOD_SHIFT) != 0;
      io.KeyAlt = (e.mods & GLFW_MOD_ALT) != 0;
      io.KeySuper = (e.mods & GLFW_MOD_SUPER) != 0;
      if (!e.pressed) {  // a released modifier clears its flag
        if (e.key == GLFW_KEY_LEFT_CONTROL || e.key == GLFW_KEY_RIGHT_CONTROL) io.KeyCtrl = false;
        if (e.key == GLFW_KEY_LEFT_SHIFT || e.key == GLFW_KEY_RIGHT_SHIFT) io.KeyShift = false;
      }
      break;
    case InputEvent::Kind::Char:
      io.AddInputCharacter(e.codepoint);
      break;
    case InputEvent::Kind::Drop:
      break;
  }
}

void ImGuiLayer::render() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantTextInput; }

}  // namespace sagrid::ui
