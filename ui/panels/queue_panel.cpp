#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "ui/app/session.h"
#include "ui/panels/panels.h"

namespace sagrid::ui {

namespace {
ImVec4 stateColor(QueueState state) {
  switch (state) {
    case QueueState::Accepted:
      return ImVec4(0.45f, 0.85f, 0.45f, 1);
    case QueueState::Edited:
      return ImVec4(0.95f, 0.75f, 0.30f, 1);
    case QueueState::Skipped:
      return ImVec4(0.60f, 0.60f, 0.65f, 1);
    case QueueState::Unreviewed:
      break;
  }
  return ImVec4(0.75f, 0.80f, 0.90f, 1);
}
}  // namespace

void drawQueuePanel(Session& session) {
  const ReviewQueue& queue = session.queue();
  if (!ImGui::CollapsingHeader("Review queue", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (queue.empty()) {
    ImGui::TextWrapped(
        "Nothing open. File > Open, drop files on the window, or pass a folder: sagrid gui DIR");
    return;
  }
  const float done = float(queue.reviewedCount()) / float(queue.size());
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%zu / %zu reviewed", queue.reviewedCount(), queue.size());
  ImGui::ProgressBar(done, ImVec2(-1, 0), overlay);
  if (ImGui::Button("< Prev (P)")) session.previous();
  ImGui::SameLine();
  if (ImGui::Button("Next (N) >")) session.next();
  ImGui::SameLine();
  if (ImGui::Button("Skip (S)")) session.skip();
  const float rows = std::min<float>(float(queue.size()), 8.0f);
  ImGui::BeginChild("queue", ImVec2(0, rows * ImGui::GetTextLineHeightWithSpacing() + 8), true);
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const QueueEntry& entry = queue.entry(i);
    ImGui::PushID(static_cast<int>(i));
    ImGui::TextColored(stateColor(entry.state), "%-10s",
                       entry.error.empty() ? toString(entry.state) : "error");
    ImGui::SameLine();
    const std::string name =
        entry.mesh.parent_path().filename().string() + "/" + entry.mesh.filename().string();
    if (ImGui::Selectable(name.c_str(), static_cast<int>(i) == queue.current()))
      session.openEntry(static_cast<int>(i));
    if (!entry.error.empty() && ImGui::IsItemHovered())
      ImGui::SetTooltip("%s", entry.error.c_str());
    ImGui::PopID();
  }
  ImGui::EndChild();
}

}  // namespace sagrid::ui
