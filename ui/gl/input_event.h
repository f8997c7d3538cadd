// Input as the application sees it, independent of where it came from: GLFW callbacks in the
// window, or a script in headless tests (which replay the same events a user would produce).
// Key and button codes are GLFW's (GLFW_KEY_*, GLFW_MOUSE_BUTTON_*), modifiers GLFW_MOD_*.
#pragma once

#include <string>
#include <vector>

namespace sagrid::ui {

struct InputEvent {
  enum class Kind { MouseMove, MouseButton, Scroll, Key, Char, Drop };
  Kind kind = Kind::MouseMove;
  float x = 0, y = 0;    // MouseMove: window coordinates (pixels, top-left origin); Scroll: offsets
  int button = 0;        // MouseButton
  int key = 0;           // Key
  bool pressed = false;  // MouseButton / Key (repeats count as pressed)
  int mods = 0;          // GLFW_MOD_* bits for MouseButton / Key
  unsigned codepoint = 0;          // Char
  std::vector<std::string> paths;  // Drop

  static InputEvent mouseMove(float x, float y);
  static InputEvent mouseButton(int button, bool pressed, int mods = 0);
  static InputEvent scroll(float dx, float dy);
  static InputEvent keyEvent(int key, bool pressed, int mods = 0);
  static InputEvent character(unsigned codepoint);
  static InputEvent drop(std::vector<std::string> paths);
};

}  // namespace sagrid::ui
