#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/app/session.h"
#include "ui/panels/panels.h"
#include "ui/render/scene_renderer.h"
#include "ui/render/type_colors.h"

namespace sagrid::ui {

void drawFieldPanel(Session& session, const SceneRenderer& scene) {
  if (!ImGui::CollapsingHeader("Distance field", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const AnnotationDocument* doc = session.document();
  FieldSettings& f = session.view().field;
  ImGui::Checkbox("Show (V)", &f.visible);
  ImGui::SameLine();
  ImGui::TextDisabled(scene.showingPredictedFields() ? "predicted" : "of the labelled points");
  if (!doc) return;
  const float mpu = doc->metersPerUnit();
  char format[16];
  std::snprintf(format, sizeof format, "%%.3f %s", doc->lengthUnit());
  const float largest = std::max(scene.field().largestDistance(), 1e-6f);
  // Sliders work in metres (what the curator thinks in); the renderer gets mesh units. ImGui
  // asserts on slider bounds beyond FLT_MAX / 2, so the top is kept finite and sane even for
  // labels built in code (files are validated on reading).
  const float top = std::isfinite(largest * mpu) ? std::clamp(largest * mpu, 2e-4f, 1e9f) : 1.0f;
  float thresholdM = std::min((f.threshold > 0 ? f.threshold : largest) * mpu, top);
  ImGui::SetNextItemWidth(-90);
  if (ImGui::SliderFloat("closer than", &thresholdM, 0.0f, top, format))
    f.threshold = thresholdM / mpu;
  float colorM = std::min((f.colorMax > 0 ? f.colorMax : largest) * mpu, top);
  ImGui::SetNextItemWidth(-90);
  if (ImGui::SliderFloat("colour max", &colorM, 1e-4f, top, format))
    f.colorMax = colorM / mpu;
  ImGui::SetNextItemWidth(-90);
  ImGui::SliderFloat("opacity", &f.opacity, 0.05f, 1.0f, "%.2f");
  const char* axes[] = {"none", "x", "y", "z"};
  int axis = f.sliceAxis + 1;
  ImGui::SetNextItemWidth(70);
  if (ImGui::Combo("slice", &axis, axes, 4)) f.sliceAxis = axis - 1;
  if (f.sliceAxis >= 0) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    ImGui::SliderFloat("##slicepos", &f.slice, 0.0f, 1.0f, "%.2f");
  }
  const auto& types = scene.field().types();
  for (std::size_t i = 0; i < types.size() && i < 32; ++i) {
    bool on = (f.typeMask >> i) & 1u;
    const Eigen::Vector3f c = typeColor(types[i]);
    ImGui::PushStyleColor(ImGuiCol_CheckMark, ImVec4(c.x(), c.y(), c.z(), 1));
    if (ImGui::Checkbox(types[i].c_str(), &on))
      f.typeMask = on ? (f.typeMask | (1u << i)) : (f.typeMask & ~(1u << i));
    ImGui::PopStyleColor();
    if (i + 1 < types.size()) ImGui::SameLine();
  }
  ImGui::TextDisabled("%d^3 grid: %zu voxels, %zu drawn", doc->gridResolution(),
                      scene.field().voxelCount(), scene.field().instanceCount());
}

}  // namespace sagrid::ui
