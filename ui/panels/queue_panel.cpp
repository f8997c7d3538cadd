#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "core/annotate/object_confidence.h"
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
    case QueueState::InProgress:
      return ImVec4(0.95f, 0.90f, 0.55f, 1);
    case QueueState::Unreviewed:
      break;
  }
  return ImVec4(0.75f, 0.80f, 0.90f, 1);
}
}  // namespace

namespace {

// Least-sure-first ordering and "accept automatically above X" with the precision measured at X.
void drawConfidenceControls(Session& session, const ConfidenceCalibration& confidence) {
  if (ImGui::Button("Least sure first")) session.orderQueueLeastSureFirst();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Order the queue by the prediction's confidence, lowest first");
  float threshold = static_cast<float>(session.autoAcceptThreshold);
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("accept above", &threshold, 0.5f, 1.0f, "%.2f"))
    session.autoAcceptThreshold = threshold;
  if (confidence.fitted && !confidence.measuredConfidence.empty()) {
    const AutoAcceptRow row =
        autoAcceptAt(confidence.measuredConfidence, confidence.measuredRight, threshold);
    if (row.coverage > 0)
      ImGui::TextWrapped("Measured at %.2f: %.0f %% of objects, %.0f %% of them right (%zu "
                         "objects of the fit)",
                         threshold, 100 * row.coverage, 100 * row.precision,
                         confidence.measuredConfidence.size());
    else
      ImGui::TextWrapped("Measured at %.2f: no object of the fit reaches it", threshold);
  } else {
    ImGui::TextWrapped("Confidence not calibrated for these models (no confidence.json)");
  }
  const std::size_t candidates =
      session.queue().unreviewedAtOrAbove(session.autoAcceptThreshold).size();
  char label[64];
  std::snprintf(label, sizeof label, "Accept %zu above %.2f", candidates,
                session.autoAcceptThreshold);
  ImGui::BeginDisabled(candidates == 0);
  if (ImGui::Button(label)) session.acceptAutomaticallyAbove(session.autoAcceptThreshold);
  ImGui::EndDisabled();
}

}  // namespace

void drawQueuePanel(Session& session, const ConfidenceCalibration& confidence) {
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
  drawConfidenceControls(session, confidence);
  const float rows = std::min<float>(float(queue.size()), 8.0f);
  ImGui::BeginChild("queue", ImVec2(0, rows * ImGui::GetTextLineHeightWithSpacing() + 8), true);
  // The list follows the queue: when the current object changes (A, N, P), its row scrolls into
  // the middle of the list; the curator's own scrolling is left alone otherwise.
  ImGuiStorage* storage = ImGui::GetStateStorage();
  const ImGuiID shownKey = ImGui::GetID("shown current");
  const bool follow = storage->GetInt(shownKey, -1) != queue.current();
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const QueueEntry& entry = queue.entry(i);
    ImGui::PushID(static_cast<int>(i));
    ImGui::TextColored(stateColor(entry.state), "%-10s",
                       entry.error.empty() ? toString(entry.state) : "error");
    ImGui::SameLine();
    if (entry.confidence)
      ImGui::Text("%3.0f%%", 100 * *entry.confidence);
    else
      ImGui::TextDisabled("  – ");
    ImGui::SameLine();
    const std::string name =
        entry.mesh.parent_path().filename().string() + "/" + entry.mesh.filename().string();
    if (ImGui::Selectable(name.c_str(), static_cast<int>(i) == queue.current()))
      session.openEntry(static_cast<int>(i));
    if (follow && static_cast<int>(i) == queue.current()) {
      ImGui::SetScrollHereY(0.5f);
      storage->SetInt(shownKey, queue.current());
    }
    if (!entry.error.empty() && ImGui::IsItemHovered())
      ImGui::SetTooltip("%s", entry.error.c_str());
    ImGui::PopID();
  }
  ImGui::EndChild();
}

}  // namespace sagrid::ui
