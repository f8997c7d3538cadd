#include "ui/gl/input_event.h"

#include <utility>

namespace sagrid::ui {

InputEvent InputEvent::mouseMove(float x, float y) {
  InputEvent e;
  e.kind = Kind::MouseMove;
  e.x = x;
  e.y = y;
  return e;
}

InputEvent InputEvent::mouseButton(int button, bool pressed, int mods) {
  InputEvent e;
  e.kind = Kind::MouseButton;
  e.button = button;
  e.pressed = pressed;
  e.mods = mods;
  return e;
}

InputEvent InputEvent::scroll(float dx, float dy) {
  InputEvent e;
  e.kind = Kind::Scroll;
  e.x = dx;
  e.y = dy;
  return e;
}

InputEvent InputEvent::keyEvent(int key, bool pressed, int mods) {
  InputEvent e;
  e.kind = Kind::Key;
  e.key = key;
  e.pressed = pressed;
  e.mods = mods;
  return e;
}

InputEvent InputEvent::character(unsigned codepoint) {
  InputEvent e;
  e.kind = Kind::Char;
  e.codepoint = codepoint;
  return e;
}

InputEvent InputEvent::drop(std::vector<std::string> paths) {
  InputEvent e;
  e.kind = Kind::Drop;
  e.paths = std::move(paths);
  return e;
}

}  // namespace sagrid::ui
