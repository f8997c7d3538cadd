// Keyboard shortcuts of the annotation GUI, one table shared by the key handler and the help
// overlay (so the overlay can never list a key that does not work).
#pragma once

#include <vector>

#include "ui/gl/input_event.h"

namespace sagrid::ui {

class Session;

struct ShortcutHelp {
  const char* keys;
  const char* action;
};
const std::vector<ShortcutHelp>& shortcutHelp();

// Handles key events (skipped while a text field has focus). Returns true if the app should quit.
bool handleShortcuts(const std::vector<InputEvent>& events, Session& session, bool textInputActive);

}  // namespace sagrid::ui
