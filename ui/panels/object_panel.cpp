#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "core/annotate/suggested_points.h"
#include "core/annotate/units_record.h"
#include "core/curation/curation_plan.h"
#include "core/mesh/mesh_import.h"
#include "ui/app/session.h"
#include "ui/document/mass_commands.h"
#include "ui/document/twin_points.h"
#include "ui/panels/panels.h"

namespace sagrid::ui {

namespace {

// Mass for the simulator exports: the estimate (solid volume x the category's density) unless the
// curator sets one (labels object.mass_kg, an undoable edit; "Estimate" clears it again).
void drawMass(Session& session, const AnnotationDocument& doc) {
  const physics::MassProperties* estimate = session.massEstimate().forDocument(doc);
  const std::optional<double> curated = curatedMass(doc.labels());
  if (estimate) {
    ImGui::TextDisabled("estimated mass %.3g kg (%.0f kg/m^3)", estimate->mass,
                        estimate->density);
  } else {
    ImGui::TextDisabled("no mass estimate: %s", session.massEstimate().error().c_str());
  }
  double value = curated ? *curated : (estimate ? estimate->mass : 0.0);
  ImGui::SetNextItemWidth(curated ? -80.0f : -1.0f);
  if (ImGui::InputDouble("##mass", &value, 0.0, 0.0, curated ? "mass %.3f kg" : "mass %.3f kg (est.)",
                         ImGuiInputTextFlags_EnterReturnsTrue) &&
      std::isfinite(value) && value > 0.0 && value <= 1e6) {
    session.execute(std::make_unique<SetMassCommand>(value));
  }
  if (curated) {
    ImGui::SameLine();
    if (ImGui::Button("Estimate", ImVec2(-1, 0)))
      session.execute(std::make_unique<SetMassCommand>(std::nullopt));
  }
}

// Units: the file's numbers in metres unless the labels say otherwise. A guessed unit (annotate,
// from plausible sizes of the category, or carried from the curator's units for another object of
// the source) is flagged until the curator picks or types one (undoable).
void drawUnits(Session& session, const AnnotationDocument& doc) {
  const std::optional<UnitGuess> guess = recordedUnitGuess(doc.labels().object);
  const double current = doc.metersPerUnit();
  const std::string shown = unitName(current);
  char label[96];
  const auto declared = doc.labels().object.extra.find(kUnitsDeclaredByField);
  const bool isDeclared =
      !guess && declared != doc.labels().object.extra.end() && declared->is_string();
  std::snprintf(label, sizeof label, "units: %s%s", shown.c_str(),
                guess              ? " (guessed)"
                : isDeclared       ? " (declared)"
                : doc.unitsKnown() ? ""
                                   : " (unknown: m assumed)");
  if (guess) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.95f, 0.75f, 0.35f, 1.0f));
  ImGui::SetNextItemWidth(-1);
  const bool open = ImGui::BeginCombo("##units", label);
  if (guess) ImGui::PopStyleColor();
  if (guess && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", guess->reason.c_str());
  if (isDeclared && ImGui::IsItemHovered())
    ImGui::SetTooltip("The object's %s declares %g m per unit (a Sweet Home 3D catalog's scale)",
                      declared->get<std::string>().c_str(), current);
  if (open) {
    for (const NamedUnit& unit : namedUnits()) {
      // Picking the guessed unit confirms it: the guess flag goes, the value stays.
      if (ImGui::Selectable(unit.name, shown == unit.name && !guess))
        session.setUnits(unit.metersPerUnit);
    }
    ImGui::EndCombo();
  }
  // Any other scale (a kit's 0.69 m per unit, decimetres): typed, applied on Enter.
  double typed = current;
  ImGui::SetNextItemWidth(-1);
  if (ImGui::InputDouble("##metres_per_unit", &typed, 0.0, 0.0, "%.6g m per unit",
                         ImGuiInputTextFlags_EnterReturnsTrue) &&
      typed != current)
    session.setUnits(typed);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Metres per file unit, for a scale the list lacks; Enter sets it (undoable).\n"
                      "Objects of the same source whose units are only guessed then open with it.");
}

}  // namespace

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
  drawUnits(session, *doc);
  const Eigen::Vector3f size = doc->mesh().bounds().sizes() * doc->metersPerUnit();
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
      if (ImGui::Selectable(c, category == c)) session.switchCategory(c);
    }
    ImGui::EndCombo();
  }
  static const std::string kKeys = [] {  // built once, not every frame
    std::string keys;
    const std::vector<std::string>& keyed = categoriesWithKeys();
    for (std::size_t i = 0; i < keyed.size(); ++i)
      keys += (i ? "  Shift+" : "Shift+") + std::to_string(i + 1) + " " + keyed[i];
    return keys;
  }();
  ImGui::TextDisabled("%s", kKeys.c_str());
  if (const auto suggested = suggestedCategory(doc->labels())) {
    // A rejected object's points are its likeliest category's: one key takes them.
    if (ImGui::Button(("take suggested: " + *suggested + " (C)").c_str(), ImVec2(-1, 0)))
      session.confirmSuggestedCategory();
  }
  if (const auto twin = pointsCarriedFrom(doc->labels())) {
    // Not the model's: a curated object of the same geometry gave them (A confirms them).
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.8f, 0.95f, 1.0f));
    ImGui::TextWrapped("points carried from %s (same geometry)", twin->c_str());
    ImGui::PopStyleColor();
  }
  if (!session.predictionNote().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.95f, 0.75f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", session.predictionNote().c_str());
    ImGui::PopStyleColor();
  }
  drawMass(session, *doc);
  const PredictionWorker& worker = session.worker();
  if (worker.running()) {
    ImGui::ProgressBar(worker.progress(), ImVec2(-70, 0), "predicting...");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) session.cancelPrediction();
  } else if (ImGui::Button("Run SAGrid", ImVec2(-1, 0))) {
    session.runPrediction();
  }
  // Off for a collection whose files are named for something else than they hold.
  ImGui::Checkbox("category reads the file's name", &session.categoryReadsFileName);
}

}  // namespace sagrid::ui
