#include <imgui.h>

#include <tuple>

#include "ui/app/session.h"
#include "ui/panels/file_browser.h"
#include "ui/panels/panels.h"

namespace sagrid::ui {

namespace {
// Export targets sit beside the object's labels unless the curator types another folder.
std::filesystem::path exportDir(const Session& session, const char* leaf) {
  const auto* doc = session.document();
  return doc ? doc->labelsPath().parent_path() / leaf : std::filesystem::path(leaf);
}
}  // namespace

bool drawMainMenu(Session& session, FileBrowser& browser) {
  bool quit = false;
  if (!ImGui::BeginMainMenuBar()) return false;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open...", "Ctrl+O")) browser.open();
    if (ImGui::BeginMenu("Recent", !session.recent().paths().empty())) {
      for (const auto& path : session.recent().paths()) {
        if (ImGui::MenuItem(path.string().c_str())) {
          const auto chosen = path;  // openPaths reorders the list we iterate
          session.openPaths({chosen});
          break;
        }
      }
      ImGui::EndMenu();
    }
    const bool hasDocument = session.document() != nullptr;
    if (ImGui::MenuItem("Save", "Ctrl+S", false, hasDocument)) session.saveNow();
    ImGui::Separator();
    if (ImGui::MenuItem("Export for OmniGibson / BEHAVIOR-1K", nullptr, false, hasDocument)) {
      session.exportCurrent("omnigibson", exportDir(session, "export-omnigibson"));
    }
    if (ImGui::MenuItem("Export MuJoCo MJCF", nullptr, false, hasDocument)) {
      session.exportCurrent("mjcf", exportDir(session, "export-mjcf"));
    }
    if (ImGui::MenuItem("Add to training set", nullptr, false, hasDocument)) {
      session.addCurrentToTrainingSet(session.trainingSetDir);
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) quit = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    ViewSettings& v = session.view();
    ImGui::MenuItem("Mesh", nullptr, &v.showMesh);
    ImGui::MenuItem("Wireframe", "W", &v.wireframe);
    for (const auto& [name, key, colouring] :
         {std::tuple{"Plain grey", "G", SurfaceColouring::PlainGrey},
          std::tuple{"Colour by material", "M", SurfaceColouring::ByMaterial},
          std::tuple{"Texture contrast", "B", SurfaceColouring::TextureContrast}})
      if (ImGui::MenuItem(name, key, v.surface == colouring)) toggleSurfaceColouring(v.surface, colouring);
    if (ImGui::MenuItem("From above", "Keypad 7")) session.viewFrom(Session::ViewSide::Top);
    if (ImGui::MenuItem("From the front", "Keypad 1")) session.viewFrom(Session::ViewSide::Front);
    if (ImGui::MenuItem("From the right", "Keypad 3")) session.viewFrom(Session::ViewSide::Right);
    bool turned = v.controlTurn != 0.0f;
    if (ImGui::MenuItem("Controls turned", "T", &turned)) v.controlTurn = turned ? kPreviewTurn : 0.0f;
    ImGui::MenuItem("Distance field", "V", &v.field.visible);
    ImGui::MenuItem("Points", nullptr, &v.showPoints);
    ImGui::MenuItem("Point labels", nullptr, &v.showPointLabels);
    ImGui::MenuItem("Ground grid", nullptr, &v.showGrid);
    ImGui::MenuItem("Axes", nullptr, &v.showAxes);
    ImGui::MenuItem("Panels", nullptr, &v.showPanels);
    ImGui::Separator();
    if (ImGui::MenuItem("Frame object")) session.frameObject();
    if (ImGui::MenuItem("Close-up of the selected point", "F", false,
                        session.document() && session.document()->selected() >= 0))
      session.frameSelection();
    if (ImGui::MenuItem("Screenshot", "F12")) session.screenshotRequested = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Shortcuts", "H")) session.showHelp = true;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
  return quit;
}

}  // namespace sagrid::ui
