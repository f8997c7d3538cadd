// The selected toggle button's control in the Points panel (issue 42): what moves, how, about
// which axis, and on a stove which burner it lights; each change one undoable command. The
// viewport draws the part and its axis (viewport_overlay.cpp).
#include <imgui.h>

#include <cstdio>
#include <memory>

#include "core/controls/control_part_edit.h"
#include "core/controls/control_record.h"
#include "ui/app/control_edit.h"
#include "ui/app/session.h"
#include "ui/document/control_commands.h"
#include "ui/document/control_view.h"
#include "ui/panels/panels.h"

namespace sagrid::ui {

namespace {

void motionCombo(Session& session, int index, const ShownControl& shown) {
  ImGui::SetNextItemWidth(110);
  if (!ImGui::BeginCombo("##motion", toString(shown.part.motion))) return;
  for (ControlMotion m : {ControlMotion::Knob, ControlMotion::Lever, ControlMotion::Button})
    if (ImGui::Selectable(toString(m), m == shown.part.motion)) setControlMotion(session, index, m);
  ImGui::EndCombo();
}

void axisButtons(Session& session, int index, ShownControl shown) {
  if (ImGui::Button("Flip axis")) {
    shown.part.axis = -shown.part.axis;
    setControlRecord(session, index, shown, "axis flipped");
  }
  ImGui::SameLine();
  const char* names[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    ImGui::SameLine();
    if (ImGui::SmallButton(names[a])) {
      shown.part.axis = Eigen::Vector3f::Unit(a);
      setControlRecord(session, index, shown, std::string("axis along ") + names[a]);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Axis along the view's %s (z up)", names[a]);
  }
  // A knob's own axis (a lever arm is nearly symmetric about its length; a disc has no surface).
  if (shown.part.motion != ControlMotion::Knob || shown.part.triangles.empty()) return;
  ImGui::SameLine();
  if (ImGui::SmallButton("own")) setOwnAxis(session, index);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Axis of the part's own rotational symmetry (a knob leaning with a sloped "
                      "panel turns about it, not about a view axis)");
}

// The burner a stove knob lights: one of the heat source points, or none.
void drivesCombo(Session& session, int index, ShownControl shown) {
  const auto& points = session.document()->points();
  std::vector<int> burners;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    if (points[std::size_t(i)].type == "heatsource") burners.push_back(i);
  if (burners.empty()) return;
  const int current = shown.drives.value_or(-1);
  char preview[64] = "no burner";
  if (current >= 0 && current < static_cast<int>(burners.size()))
    std::snprintf(preview, sizeof preview, "burner: point %d", burners[std::size_t(current)] + 1);
  ImGui::SetNextItemWidth(-1);
  if (!ImGui::BeginCombo("##drives", preview)) return;
  for (int k = -1; k < static_cast<int>(burners.size()); ++k) {
    char label[64] = "no burner";
    if (k >= 0) std::snprintf(label, sizeof label, "burner: point %d", burners[std::size_t(k)] + 1);
    if (ImGui::Selectable(label, k == current) && k != current) {
      shown.drives = k;
      setControlRecord(session, index, shown, label);
    }
  }
  ImGui::EndCombo();
}

// The viewport's part brush: on or off, and its radius.
void brushControls(Session& session) {
  ImGui::Checkbox("Brush", &session.partBrush.armed);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("While on, a click on the surface adds what lies within the radius and is "
                      "connected to the clicked surface to the part; Ctrl+click takes it away, "
                      "Alt+click starts the part anew with it");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  ImGui::SliderFloat("radius (cm)", &session.partBrush.radiusCm, 0.2f, 10.0f, "%.1f",
                     ImGuiSliderFlags_Logarithmic);
}

// Grow or shrink the part by one ring of triangles, or brush it in the viewport (its motion found
// again from its new shape); or put the pivot at the point itself.
void partButtons(Session& session, int index, ShownControl shown) {
  // The welded surface is asked for only on a click: drawing the panel welds nothing.
  if (ImGui::Button("Grow"))
    reshapeControlPart(session, index,
                       grownPart(session.document()->partEditSurface(), shown.part.triangles),
                       "part grown");
  ImGui::SameLine();
  if (ImGui::Button("Shrink"))
    reshapeControlPart(session, index,
                       shrunkPart(session.document()->partEditSurface(), shown.part.triangles),
                       "part shrunk");
  ImGui::SameLine();
  if (ImGui::Button("Pivot at the point")) {
    shown.part.pivot = session.document()->pointInView(index);
    setControlRecord(session, index, shown, "pivot at the point");
  }
  brushControls(session);
}

}  // namespace

void drawControlEditor(Session& session, int index) {
  const AnnotationDocument& doc = *session.document();
  const std::optional<ShownControl> shown = shownControl(doc, index);
  ImGui::Separator();
  ImGui::TextUnformatted("Control");
  if (!shown) {
    ImGui::TextDisabled("No part moves here: a site only in the exports. Brush one on:");
    brushControls(session);
    return;
  }
  ImGui::Text("%s, %zu triangles (%s)%s", toString(shown->part.motion),
              shown->part.triangles.size(), toString(shown->part.origin),
              shown->confirmed ? ", confirmed" : shown->recorded ? "" : ", found now");
  if (!shown->warning.empty()) ImGui::TextWrapped("%s", shown->warning.c_str());
  motionCombo(session, index, *shown);
  ImGui::SameLine();
  axisButtons(session, index, *shown);
  partButtons(session, index, *shown);
  drivesCombo(session, index, *shown);
  if (!shown->confirmed) {
    if (ImGui::Button("Keep this part")) setControlRecord(session, index, *shown, "part kept");
    ImGui::SameLine();
  }
  if (ImGui::Button("Keep all")) confirmEveryControl(session);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Every toggle button's part and motion kept as shown (one step)");
  ImGui::SameLine();
  if (ImGui::Button("This axis for all")) confirmEveryControl(session, index);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Every control that moves as this one does gets its axis (one step)");
  if (shown->recorded) {
    if (ImGui::Button("Find the part again"))
      session.execute(std::make_unique<SetControlCommand>(index, nlohmann::json(), "found again"));
  }
}

}  // namespace sagrid::ui
