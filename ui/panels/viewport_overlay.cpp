#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/controls/control_turn.h"
#include "ui/app/label_layout.h"
#include "ui/app/point_visibility.h"
#include "ui/app/session.h"
#include "ui/document/control_view.h"
#include "ui/document/twin_points.h"
#include "ui/panels/panels.h"
#include "ui/render/colormap.h"
#include "ui/render/scene_renderer.h"
#include "ui/render/type_colors.h"

namespace sagrid::ui {

namespace {
ImU32 toU32(const Eigen::Vector3f& c, float a = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x(), c.y(), c.z(), a));
}

void pointLabels(const Session& session, ImDrawList* draw) {
  const AnnotationDocument* doc = session.document();
  const ViewportRect& vp = session.viewport();
  struct Shown {
    int index;
    bool hidden;
    char full[96], number[16];
    ImVec2 fullSize, numberSize;
  };
  // Drawn every frame: the buffers and the layout's are kept from one frame to the next.
  static std::vector<Shown> shown;
  static std::vector<LabelRequest> requests;
  static LabelLayout layout;
  shown.clear();
  requests.clear();
  for (int i = 0; i < static_cast<int>(doc->points().size()); ++i) {
    Eigen::Vector2f pixel;
    if (!session.camera().project(doc->pointInView(i), pixel)) continue;
    // Far off screen: nothing to draw, and ImGui's text clipping misbehaves at huge coordinates.
    const float margin = 4096.0f;
    if (pixel.x() < -margin || pixel.y() < -margin || pixel.x() > vp.width + margin ||
        pixel.y() > vp.height + margin)
      continue;
    const ImVec2 at(vp.x + pixel.x(), vp.y + pixel.y());
    const AffordancePoint& p = doc->points()[std::size_t(i)];
    if (doc->selected() == i)
      draw->AddCircle(at, session.view().markerPixels * 1.35f + 4, IM_COL32(255, 255, 255, 230), 24,
                      2.0f);
    if (!session.view().showPointLabels) continue;
    Shown& s = shown.emplace_back();
    s.index = i;
    // A point the surface hides keeps a faint label: the near ones of a row of knobs stay legible.
    s.hidden = pointHiddenFromEye(*doc, session.camera().eye(), i);
    std::snprintf(s.full, sizeof s.full, "%d %s%s", i + 1, p.type.c_str(),
                  p.status == AffordanceStatus::Predicted ? " ?" : "");
    std::snprintf(s.number, sizeof s.number, "%d", i + 1);
    s.fullSize = ImGui::CalcTextSize(s.full);
    s.numberSize = ImGui::CalcTextSize(s.number);
    // Labels placed so that a row of knobs' do not pile up: the selected point's first, then the
    // points the eye sees; centred so that the right-hand spot puts the text where it always was
    // (8 px above the marker's centre).
    const float centreY = at.y - 9.0f + (s.fullSize.y + 2) / 2;
    requests.push_back({{at.x, centreY},
                        {s.fullSize.x + 6, s.fullSize.y + 2},
                        {s.numberSize.x + 6, s.numberSize.y + 2},
                        doc->selected() == i ? 0 : s.hidden ? 2 : 1});
  }
  const auto& placed = layout.place(requests, session.view().markerPixels + 1);
  for (std::size_t k = 0; k < shown.size(); ++k) {
    const Shown& s = shown[k];
    const char* text = placed[k].shortened ? s.number : s.full;
    const ImVec2 size = placed[k].shortened ? s.numberSize : s.fullSize;
    const ImVec2 box(placed[k].topLeft.x(), placed[k].topLeft.y());
    draw->AddRectFilled(box, ImVec2(box.x + size.x + 6, box.y + size.y + 2),
                        IM_COL32(15, 17, 20, s.hidden ? 60 : 190), 3.0f);
    draw->AddText(ImVec2(box.x + 3, box.y + 1),
                  toU32(typeColor(doc->points()[std::size_t(s.index)].type), s.hidden ? 0.35f : 1.0f),
                  text);
  }
}

// The selected toggle button's moving part, translucent, and the axis it turns about (or slides
// along) through its pivot.
void selectedControl(const Session& session, ImDrawList* draw) {
  const AnnotationDocument* doc = session.document();
  const auto shown = shownControl(*doc, doc->selected());
  if (!shown) return;
  const ViewportRect& vp = session.viewport();
  const Mesh& mesh = doc->mesh();
  const auto toScreen = [&](const Eigen::Vector3f& p, ImVec2& out) {
    Eigen::Vector2f pixel;
    if (!session.camera().project(p, pixel)) return false;
    out = ImVec2(vp.x + pixel.x(), vp.y + pixel.y());
    return true;
  };
  constexpr std::size_t kMaxDrawn = 20000;  // a highlight, not a second renderer
  const ImU32 fill = IM_COL32(90, 230, 110, 70);
  // Where the mesh is drawn with its controls turned (T), the highlight moves with the part.
  const float turn = session.view().controlTurn;
  const Eigen::Affine3f motion =
      controlMotion(shown->part, turn, pressAtTurn(turn, sagrid::metersPerUnit(doc->labels())));
  const auto at = [&](int v) -> Eigen::Vector3f { return motion * mesh.positions[static_cast<std::size_t>(v)]; };
  for (std::size_t i = 0; i < shown->part.triangles.size() && i < kMaxDrawn; ++i) {
    const auto& t = mesh.triangles[static_cast<std::size_t>(shown->part.triangles[i])];
    ImVec2 a, b, c;
    if (toScreen(at(t[0]), a) && toScreen(at(t[1]), b) && toScreen(at(t[2]), c))
      draw->AddTriangleFilled(a, b, c, fill);
  }
  // The axis through the pivot, left out around the point's marker so the marker stays visible.
  const float reach = std::max(shown->part.radius * 2.0f, 1e-3f * mesh.bounds().diagonal().norm());
  const ImU32 yellow = IM_COL32(255, 220, 60, 255);
  ImVec2 pivot, from, to, marker;
  if (!toScreen(shown->part.pivot, pivot) ||
      !toScreen(shown->part.pivot - reach * shown->part.axis, from) ||
      !toScreen(shown->part.pivot + reach * shown->part.axis, to))
    return;
  const bool markerShown = toScreen(doc->pointInView(doc->selected()), marker);
  const float clear = session.view().markerPixels * 1.35f + 6.0f;
  const auto segment = [&](ImVec2 a, ImVec2 b) {
    // From a to b, less the part within `clear` of the marker (a circle cut out of the segment).
    const float dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    if (!markerShown || length2 <= 0) return draw->AddLine(a, b, yellow, 2.5f);
    const float t = std::clamp(((marker.x - a.x) * dx + (marker.y - a.y) * dy) / length2, 0.0f, 1.0f);
    const float cx = a.x + t * dx - marker.x, cy = a.y + t * dy - marker.y;
    const float gap2 = clear * clear - (cx * cx + cy * cy);
    if (gap2 <= 0) return draw->AddLine(a, b, yellow, 2.5f);
    const float half = std::sqrt(gap2 / length2);
    if (t - half > 0) draw->AddLine(a, ImVec2(a.x + (t - half) * dx, a.y + (t - half) * dy), yellow, 2.5f);
    if (t + half < 1) draw->AddLine(ImVec2(a.x + (t + half) * dx, a.y + (t + half) * dy), b, yellow, 2.5f);
  };
  segment(from, pivot);
  segment(pivot, to);
  draw->AddCircleFilled(to, 4.0f, yellow);
}

// The world axes as seen by the camera, in the viewport's bottom-left corner.
void axesGizmo(const Session& session, ImDrawList* draw) {
  const ViewportRect& vp = session.viewport();
  const ImVec2 origin(vp.x + 48, vp.y + vp.height - 48);
  const Eigen::Matrix4f view = session.camera().view();
  const char* names[] = {"X", "Y", "Z"};
  const Eigen::Vector3f colors[] = {
      {0.90f, 0.30f, 0.30f}, {0.40f, 0.85f, 0.35f}, {0.35f, 0.55f, 1.0f}};
  draw->AddCircleFilled(origin, 40, IM_COL32(20, 22, 26, 150), 32);
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3f dir = view.block<3, 3>(0, 0).col(a);
    const ImVec2 tip(origin.x + dir.x() * 30, origin.y - dir.y() * 30);
    draw->AddLine(origin, tip, toU32(colors[a]), 2.5f);
    draw->AddText(ImVec2(tip.x - 4, tip.y - 8), toU32(colors[a]), names[a]);
  }
}

void legend(const Session& session, const SceneRenderer& scene, ImDrawList* draw) {
  const FieldSettings& f = session.view().field;
  if (!f.visible || scene.field().instanceCount() == 0) return;
  const ViewportRect& vp = session.viewport();
  const float mpu = session.document()->metersPerUnit();
  const float colorMax = f.colorMax > 0 ? f.colorMax : scene.field().largestDistance();
  const float w = std::min(220.0f, vp.width - 120.0f), h = 12;  // leaves room for the axes gizmo
  if (w < 80.0f) return;
  const ImVec2 at(vp.x + vp.width - w - 24, vp.y + vp.height - 52);
  draw->AddRectFilled(ImVec2(at.x - 10, at.y - 24), ImVec2(at.x + w + 10, at.y + h + 22),
                      IM_COL32(20, 22, 26, 190), 5.0f);
  char title[64];
  std::snprintf(title, sizeof title, "distance to nearest point (%s)",
                session.document()->lengthUnit());
  draw->AddText(ImVec2(at.x, at.y - 20), IM_COL32(220, 224, 230, 255), title);
  const int steps = 44;
  for (int s = 0; s < steps; ++s) {
    const float t0 = float(s) / steps, t1 = float(s + 1) / steps;
    draw->AddRectFilled(ImVec2(at.x + t0 * w, at.y), ImVec2(at.x + t1 * w + 0.5f, at.y + h),
                        toU32(distanceColor(t0 * colorMax, colorMax)));
  }
  for (int k = 0; k <= 4; ++k) {
    char label[32];
    // Enough decimals that the ticks differ (small objects span millimetres).
    const float top = colorMax * mpu;
    const char* format = top >= 100.0f  ? "%.0f"
                         : top >= 10.0f ? "%.1f"
                         : top >= 0.4f  ? "%.2f"
                                        : "%.3f";
    std::snprintf(label, sizeof label, format, top * float(k) / 4.0f);
    const float x = at.x + w * float(k) / 4.0f;
    draw->AddLine(ImVec2(x, at.y + h), ImVec2(x, at.y + h + 3), IM_COL32(220, 224, 230, 255));
    const float tw = ImGui::CalcTextSize(label).x;
    draw->AddText(ImVec2(std::min(x - tw * 0.5f, at.x + w + 8 - tw), at.y + h + 3),
                  IM_COL32(220, 224, 230, 255), label);
  }
}
}  // namespace

void drawViewportOverlay(const Session& session, const SceneRenderer& scene) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  if (session.view().showAxes) axesGizmo(session, draw);
  if (!session.document()) {
    const ViewportRect& vp = session.viewport();
    const char* hint = "Drop meshes or a folder here, or File > Open (Ctrl+O)";
    const ImVec2 size = ImGui::CalcTextSize(hint);
    draw->AddText(ImVec2(vp.x + 0.5f * (vp.width - size.x), vp.y + 0.5f * vp.height),
                  IM_COL32(170, 175, 185, 255), hint);
    return;
  }
  if (session.view().showPoints) selectedControl(session, draw);
  if (session.view().showPoints) pointLabels(session, draw);
  legend(session, scene, draw);
}

void drawStatusBar(Session& session) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float height = ImGui::GetFrameHeight() + 6;
  ImGui::SetNextWindowPos(ImVec2(0, display.y - height));
  ImGui::SetNextWindowSize(ImVec2(display.x, height));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8, 3));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const AnnotationDocument* doc = session.document();
  if (!session.queue().empty()) {
    ImGui::Text("Object %d / %zu", session.queue().current() + 1, session.queue().size());
    ImGui::SameLine();
  }
  if (doc) {
    ImGui::TextDisabled("| %s | %zu points | %s", doc->displayName().c_str(), doc->points().size(),
                        doc->canUndo() ? ("undo: " + doc->undoDescription()).c_str() : "no edits");
    ImGui::SameLine();
  }
  if (const auto twin = doc ? pointsCarriedFrom(doc->labels()) : std::nullopt) {
    ImGui::TextColored(ImVec4(0.55f, 0.8f, 0.95f, 1), "| points carried from %s (same geometry)",
                       twin->c_str());
    ImGui::SameLine();
  }
  if (session.addModeArmed) {
    ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "| click the surface to add a %s",
                       session.currentType().c_str());
    ImGui::SameLine();
  }
  if (session.worker().running()) {
    ImGui::TextUnformatted("| predicting");
    ImGui::SameLine();
    ImGui::ProgressBar(session.worker().progress(), ImVec2(120, 0));
    ImGui::SameLine();
    if (ImGui::SmallButton("cancel")) session.cancelPrediction();
    ImGui::SameLine();
  }
  if (ImGui::GetCursorPosX() < display.x - 130) {
    ImGui::SetCursorPosX(display.x - 130);
    ImGui::TextDisabled("H: shortcuts");
  }
  ImGui::End();
  ImGui::PopStyleVar(2);
}

}  // namespace sagrid::ui
