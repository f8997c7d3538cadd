#include "ui/app/shortcuts.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/curation/curation_plan.h"
#include "ui/app/session.h"

namespace sagrid::ui {

const std::vector<ShortcutHelp>& shortcutHelp() {
  static const std::vector<ShortcutHelp> kHelp = {
      {"Left drag", "orbit (on a point: drag it along the surface)"},
      {"Right / middle drag", "pan"},
      {"Wheel, + / -", "zoom"},
      {"Arrows (Shift: pan)", "orbit"},
      {"Click", "select a point (empty space: deselect)"},
      {"Shift+click, Insert then click", "add a point of the current type"},
      {"Click, Ctrl+, Alt+click (Brush on)", "brush the selected control's part on, away, anew"},
      {"A", "accept the selected predicted point; else accept all and go to the next object"},
      {"C", "take the suggested category of a rejected object, with its points"},
      {"Del / Backspace", "delete the selected point"},
      {"Shift+Del", "delete the selected point and every later one of its type"},
      {"R", "copies: the selected point's type on every copy of its part (a row of knobs, burners)"},
      {"E", "extend the row: a point one step past the selected one, from its nearest of its type"},
      {"1-9", "current type, the category's own first (and the selected point's type)"},
      {"Shift+1 / 2 / 3", "category stove / sink / none (points predicted again for it)"},
      {"N / P", "next / previous object"},
      {"S", "skip object"},
      {"F", "close-up of the selected point; again (or none selected): the whole object"},
      {"Keypad 7 / 1 / 3", "the whole object from above / the front / the right"},
      {"W", "wireframe"},
      {"G", "plain grey: the mesh without its colours (a black model's shape)"},
      {"M", "a colour per material: parts that differ only by material (dark keys on dark glass) stand out"},
      {"B", "texture contrast: marks printed faintly in a texture (a ceramic hob's keys) stand out"},
      {"T", "controls turned as the exports turn them (a knob's part seen moving) / as modelled"},
      {"V", "distance field on/off"},
      {"Ctrl+Z", "undo"},
      {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
      {"Ctrl+S", "save now (every change is saved anyway)"},
      {"Ctrl+O", "open files or a folder"},
      {"F12", "screenshot to the current folder"},
      {"Esc", "deselect, cancel add"},
      {"H, F1", "this help"},
      {"Ctrl+Q", "quit"},
  };
  return kHelp;
}

bool handleShortcuts(const std::vector<InputEvent>& events, Session& session,
                     bool textInputActive) {
  for (const InputEvent& e : events) {
    if (e.kind != InputEvent::Kind::Key || !e.pressed || textInputActive) continue;
    const bool ctrl = (e.mods & GLFW_MOD_CONTROL) != 0;
    const bool shift = (e.mods & GLFW_MOD_SHIFT) != 0;
    if (ctrl) {
      switch (e.key) {
        case GLFW_KEY_Z:
          shift ? session.redo() : session.undo();
          break;
        case GLFW_KEY_Y:
          session.redo();
          break;
        case GLFW_KEY_S:
          session.saveNow();
          break;
        case GLFW_KEY_O:
          session.showFileBrowser = true;
          break;
        case GLFW_KEY_Q:
          return true;
        default:
          break;
      }
      continue;
    }
    if (e.key >= GLFW_KEY_1 && e.key <= GLFW_KEY_9) {
      const std::size_t index = std::size_t(e.key - GLFW_KEY_1);
      if (shift) {
        const std::vector<std::string>& categories = categoriesWithKeys();
        if (index < categories.size()) session.switchCategory(categories[index], CurationAction::CategoryKey);
        continue;
      }
      const std::vector<std::string> types = session.typesForKeys();
      if (index < types.size()) session.changeSelectedType(types[index]);
      continue;
    }
    switch (e.key) {
      case GLFW_KEY_A:
        session.accept();
        break;
      case GLFW_KEY_DELETE:
      case GLFW_KEY_BACKSPACE:
        if (shift)
          session.deleteRestOfSelected();
        else
          session.deleteSelected();
        break;
      case GLFW_KEY_N:
        session.navigate(+1);
        break;
      case GLFW_KEY_P:
        session.navigate(-1);
        break;
      case GLFW_KEY_S:
        session.skip();
        break;
      case GLFW_KEY_C:
        session.confirmSuggestedCategory();
        break;
      case GLFW_KEY_R:
        session.addOnCopiesOfSelected();
        break;
      case GLFW_KEY_E:
        session.extendRowOfSelected();
        break;
      case GLFW_KEY_F:
        session.frameSelection();
        session.noteLook("close-up");
        break;
      case GLFW_KEY_W:
        session.view().wireframe = !session.view().wireframe;
        break;
      case GLFW_KEY_KP_7:
        session.viewFrom(Session::ViewSide::Top);
        break;
      case GLFW_KEY_KP_1:
        session.viewFrom(Session::ViewSide::Front);
        break;
      case GLFW_KEY_KP_3:
        session.viewFrom(Session::ViewSide::Right);
        break;
      case GLFW_KEY_G:
        toggleSurfaceColouring(session.view().surface, SurfaceColouring::PlainGrey);
        break;
      case GLFW_KEY_M:
        toggleSurfaceColouring(session.view().surface, SurfaceColouring::ByMaterial);
        break;
      case GLFW_KEY_B:
        toggleSurfaceColouring(session.view().surface, SurfaceColouring::TextureContrast);
        break;
      case GLFW_KEY_T:
        session.view().controlTurn = session.view().controlTurn != 0.0f ? 0.0f : kPreviewTurn;
        break;
      case GLFW_KEY_V:
        session.view().field.visible = !session.view().field.visible;
        break;
      case GLFW_KEY_H:
      case GLFW_KEY_F1:
        session.showHelp = !session.showHelp;
        break;
      case GLFW_KEY_INSERT:
        session.addModeArmed = true;
        break;
      case GLFW_KEY_F12:
        session.screenshotRequested = true;
        break;
      case GLFW_KEY_ESCAPE:
        session.addModeArmed = false;
        session.showHelp = false;
        if (session.document()) session.document()->select(-1);
        break;
      case GLFW_KEY_LEFT:
        shift ? session.camera().pan(20, 0) : session.camera().orbit(0.08f, 0);
        session.noteLook("arrow keys");
        break;
      case GLFW_KEY_RIGHT:
        shift ? session.camera().pan(-20, 0) : session.camera().orbit(-0.08f, 0);
        session.noteLook("arrow keys");
        break;
      case GLFW_KEY_UP:
        shift ? session.camera().pan(0, 20) : session.camera().orbit(0, 0.08f);
        session.noteLook("arrow keys");
        break;
      case GLFW_KEY_DOWN:
        shift ? session.camera().pan(0, -20) : session.camera().orbit(0, -0.08f);
        session.noteLook("arrow keys");
        break;
      case GLFW_KEY_EQUAL:
      case GLFW_KEY_KP_ADD:
        session.camera().zoom(1);
        session.noteLook("zoom");
        break;
      case GLFW_KEY_MINUS:
      case GLFW_KEY_KP_SUBTRACT:
        session.camera().zoom(-1);
        session.noteLook("zoom");
        break;
      default:
        break;
    }
  }
  return false;
}

}  // namespace sagrid::ui
