#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "ui/app/session.h"
#include "ui/document/point_commands.h"
#include "ui/panels/panels.h"
#include "ui/render/type_colors.h"

namespace sagrid::ui {

namespace {
ImVec4 toImGui(const Eigen::Vector3f& c) { return ImVec4(c.x(), c.y(), c.z(), 1.0f); }

// True once the last item has been hovered for `seconds` without a break: a row's tooltip then
// covers the next row only when asked for, not on every pass of the pointer.
bool hoveredFor(float seconds) {
  ImGuiStorage* storage = ImGui::GetStateStorage();
  const ImGuiID sinceKey = ImGui::GetID("hovered since");  // the row's own (inside its PushID)
  if (!ImGui::IsItemHovered()) {
    storage->SetFloat(sinceKey, -1.0f);
    return false;
  }
  float since = storage->GetFloat(sinceKey, -1.0f);
  if (since < 0.0f) storage->SetFloat(sinceKey, since = float(ImGui::GetTime()));
  return float(ImGui::GetTime()) - since >= seconds;
}

// The selected row in a colour of its own: the hovered one is the blue of every list, and A's
// effect depends on which point is selected.
const ImVec4 kSelectedRow(0.80f, 0.52f, 0.16f, 0.60f);

void typeSelector(Session& session) {
  ImGui::TextUnformatted("New points:");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  // Each type with its number key (the category's own types first), the current one too.
  const std::vector<std::string> types = session.typesForKeys();
  auto withKey = [&types](const std::string& type) {
    const auto at = std::find(types.begin(), types.end(), type);
    char label[96];
    if (at == types.end()) std::snprintf(label, sizeof label, "%s", type.c_str());
    else std::snprintf(label, sizeof label, "%d  %s", int(at - types.begin()) + 1, type.c_str());
    return std::string(label);
  };
  if (ImGui::BeginCombo("##type", withKey(session.currentType()).c_str())) {
    for (std::size_t i = 0; i < types.size(); ++i) {
      const std::string label = withKey(types[i]);
      ImGui::PushStyleColor(ImGuiCol_Text, toImGui(typeColor(types[i])));
      if (ImGui::Selectable(label.c_str(), types[i] == session.currentType()))
        session.setCurrentType(types[i]);
      ImGui::PopStyleColor();
    }
    ImGui::EndCombo();
  }
}

// Exact coordinates of the selected point (mesh file frame), applied as one command on Enter.
void coordinateEditor(Session& session, int index) {
  const AnnotationDocument& doc = *session.document();
  const AffordancePoint& point = doc.points()[std::size_t(index)];
  float xyz[3] = {point.position.x(), point.position.y(), point.position.z()};
  ImGui::SetNextItemWidth(-1);
  if (ImGui::InputFloat3("##xyz", xyz, "%.4f", ImGuiInputTextFlags_EnterReturnsTrue)) {
    session.execute(makeSetCoordinatesCommand(index, Eigen::Vector3f(xyz[0], xyz[1], xyz[2])));
  }
}
}  // namespace

void drawPointsPanel(Session& session) {
  AnnotationDocument* doc = session.document();
  if (!ImGui::CollapsingHeader("Points", ImGuiTreeNodeFlags_DefaultOpen) || !doc) return;
  typeSelector(session);
  if (ImGui::Button(session.addModeArmed ? "Click the surface..." : "Add point (Ins)"))
    session.addModeArmed = !session.addModeArmed;
  ImGui::SameLine();
  ImGui::BeginDisabled(!doc->canUndo());
  if (ImGui::Button("Undo")) session.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!doc->canRedo());
  if (ImGui::Button("Redo")) session.redo();
  ImGui::EndDisabled();

  const auto& points = doc->points();
  if (points.empty()) ImGui::TextDisabled("No points yet: Shift+click the surface to add one.");
  const float mpu = doc->metersPerUnit();
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const AffordancePoint& p = points[std::size_t(i)];
    ImGui::PushID(i);
    ImGui::ColorButton("##c", toImGui(typeColor(p.type)), ImGuiColorEditFlags_NoTooltip,
                       ImVec2(12, 12));
    ImGui::SameLine();
    char label[160];
    std::snprintf(label, sizeof label, "%d  %-13s %s", i + 1, p.type.c_str(), toString(p.status));
    ImGui::PushStyleColor(ImGuiCol_Header, kSelectedRow);
    if (ImGui::Selectable(label, doc->selected() == i)) doc->select(i);
    ImGui::PopStyleColor();
    if (hoveredFor(0.6f)) {
      ImGui::SetTooltip("(%.4f, %.4f, %.4f) file frame%s", p.position.x(), p.position.y(),
                        p.position.z(), mpu != 1.0f ? " (units scaled to metres on export)" : "");
    }
    ImGui::PopID();
  }
  const int selected = doc->selected();
  if (selected >= 0) {
    ImGui::Separator();
    ImGui::Text("Point %d (%s)", selected + 1, points[std::size_t(selected)].type.c_str());
    coordinateEditor(session, selected);
    // As A: a predicted point is accepted alone; any other lets the object go on.
    const bool predicted = points[std::size_t(selected)].status == AffordanceStatus::Predicted;
    if (ImGui::Button(predicted ? "Accept (A)" : "Accept all (A)")) session.accept();
    if (!predicted && ImGui::IsItemHovered())
      ImGui::SetTooltip("Accept every point and go to the next object");
    ImGui::SameLine();
    if (ImGui::Button("Delete (Del)")) session.deleteSelected();
    ImGui::SameLine();
    if (ImGui::Button("Copies (R)")) session.addOnCopiesOfSelected();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Add this point's type on every copy of its part (a row of knobs, burners)");
    ImGui::SameLine();
    if (ImGui::BeginCombo("##settype", "Type", ImGuiComboFlags_NoPreview)) {
      for (const auto& type : knownTypes()) {
        if (ImGui::Selectable(type.c_str(), type == points[std::size_t(selected)].type))
          session.changeSelectedType(type);
      }
      ImGui::EndCombo();
    }
    // Its own line: the row above fills the panel's width.
    if (ImGui::Button("Delete rest (Shift+Del)")) session.deleteRestOfSelected();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Delete this point and every point of its type listed after it");
    ImGui::SameLine();
    if (ImGui::Button("Extend (E)")) session.extendRowOfSelected();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Add a point one step past this one, the step from its nearest point of its type\n"
          "(keys printed on a glass top, knobs fused into the panel)");
    if (points[std::size_t(selected)].type == "togglebutton") drawControlEditor(session, selected);
  } else if (!points.empty()) {
    if (ImGui::Button("Accept all and next (A)", ImVec2(-1, 0))) session.accept();
  }
}

}  // namespace sagrid::ui
