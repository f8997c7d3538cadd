#include <imgui.h>

#include "ui/panels/panels.h"

namespace sagrid::ui {

void drawLogPanel(const LogBuffer& log) {
  if (!ImGui::CollapsingHeader("Log")) return;
  ImGui::BeginChild("log", ImVec2(0, 140), true, ImGuiWindowFlags_HorizontalScrollbar);
  for (const LogLine& line : log.lines()) {
    const ImVec4 color = line.level >= spdlog::level::err    ? ImVec4(1.0f, 0.45f, 0.45f, 1)
                         : line.level == spdlog::level::warn ? ImVec4(1.0f, 0.8f, 0.35f, 1)
                                                             : ImVec4(0.75f, 0.78f, 0.82f, 1);
    ImGui::TextColored(color, "%s", line.text.c_str());
  }
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY())
    ImGui::SetScrollHereY(1.0f);  // follow the tail
  ImGui::EndChild();
}

}  // namespace sagrid::ui
