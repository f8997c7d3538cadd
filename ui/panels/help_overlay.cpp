#include <imgui.h>

#include "ui/app/session.h"
#include "ui/app/shortcuts.h"
#include "ui/panels/panels.h"

namespace sagrid::ui {

void drawHelpOverlay(Session& session) {
  if (!session.showHelp) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.92f);
  if (ImGui::Begin("Shortcuts", &session.showHelp,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                       ImGuiWindowFlags_NoMove)) {
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
      for (const ShortcutHelp& s : shortcutHelp()) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1), "%s", s.keys);
        ImGui::TableSetColumnIndex(1);
        ImGui::TextUnformatted(s.action);
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

void drawErrorModal(Session& session) {
  if (session.pendingErrors().empty()) return;
  if (!ImGui::IsPopupOpen("Error")) ImGui::OpenPopup("Error");
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(480, 0));
  if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_NoMove)) {
    ImGui::TextWrapped("%s", session.pendingErrors().front().c_str());
    if (session.pendingErrors().size() > 1)
      ImGui::TextDisabled("(%zu more)", session.pendingErrors().size() - 1);
    if (ImGui::Button("OK", ImVec2(120, 0)) ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
      session.dismissError();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

}  // namespace sagrid::ui
