#include <imgui.h>

#include <cstdio>

#include "core/mesh/mesh_import.h"
#include "ui/app/session.h"
#include "ui/panels/panels.h"

namespace sagrid::ui {

void drawObjectPanel(Session& session) {
  AnnotationDocument* doc = session.document();
  if (!ImGui::CollapsingHeader("Object", ImGuiTreeNodeFlags_DefaultOpen) || !doc) return;
  ImGui::TextWrapped("%s", doc->displayName().c_str());
  ImGui::TextDisabled("%zu vertices, %zu triangles", doc->mesh().vertexCount(),
                      doc->mesh().triangleCount());
  // The file's up axis; a detected one shows how sure the detection was (--up or a labelled
  // file fixes it).
  if (const auto& confidence = doc->labels().object.upConfidence) {
    ImGui::TextDisabled("up %s (detected, confidence %.2f)", doc->labels().object.up.c_str(),
                        *confidence);
  } else {
    ImGui::TextDisabled("up %s", doc->labels().object.up.c_str());
  }
  // Turning the up axis is an undoable command; the prediction runs again for the new axis.
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##up", "turn up axis...")) {
    for (UpAxis up : kAllUpAxes) {
      if (ImGui::Selectable(toString(up), up == doc->mesh().fileUp)) session.turnUpAxis(up);
    }
    ImGui::EndCombo();
  }
  const auto size = doc->mesh().bounds().sizes() * doc->metersPerUnit();
  ImGui::TextDisabled("size %.3f x %.3f x %.3f %s", size.x(), size.y(), size.z(),
                      doc->lengthUnit());
  // Category: retrieval/prediction fills it; the curator can override (training is per category).
  // "none": the category classifier's rejection (no points predicted).
  static const char* kCategories[] = {"stove", "sink", "none", "microwave", "oven", "lamp", "other"};
  const std::string& category = doc->labels().object.category;
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##category", category.empty() ? "category: unknown"
                                                       : ("category: " + category).c_str())) {
    for (const char* c : kCategories) {
      if (ImGui::Selectable(c, category == c)) doc->setCategory(c);
    }
    ImGui::EndCombo();
  }
  const PredictionWorker& worker = session.worker();
  if (worker.running()) {
    ImGui::ProgressBar(worker.progress(), ImVec2(-70, 0), "predicting...");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) session.cancelPrediction();
  } else if (ImGui::Button("Run SAGrid", ImVec2(-1, 0))) {
    session.runPrediction();
  }
}

}  // namespace sagrid::ui
