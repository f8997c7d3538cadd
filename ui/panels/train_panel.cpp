#include <imgui.h>

#include <cfloat>

#include "ui/app/session.h"
#include "ui/app/training_worker.h"
#include "ui/panels/panels.h"

namespace sagrid::ui {

void drawTrainPanel(Session& session, TrainingWorker& worker,
                    const std::filesystem::path& modelsOut,
                    const std::filesystem::path& initModels) {
  if (!ImGui::CollapsingHeader("Train")) return;
  static float minutes = 1.0f;  // UI preference only, not document state
  static char heldOut[512] = "";  // curated objects of other sources: the guard's
  static bool keepInit = false;   // the fine-tuned network joins the loaded ones
  const AnnotationDocument* doc = session.document();
  const std::string category = doc ? doc->labels().object.category : std::string();
  ImGui::TextWrapped("Training set: %s", session.trainingSetDir.string().c_str());
  if (!initModels.empty())
    ImGui::TextWrapped("Fine-tunes %s with the bench replay", initModels.string().c_str());
  const TrainingStatus status = worker.status();
  if (!status.running) {
    ImGui::SetNextItemWidth(-110);
    ImGui::SliderFloat("min / model", &minutes, 0.2f, 10.0f, "%.1f");
    if (!initModels.empty()) {
      ImGui::SetNextItemWidth(-110);
      ImGui::InputText("held out", heldOut, sizeof heldOut);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "A dataset of curated objects from other sources than the training set: "
            "each fine-tuned model is adopted only where it is better there beyond "
            "the noise of its objects");
      if (heldOut[0] == '\0')
        ImGui::TextDisabled(
            "Guard: the training set's sources left out in turn (about 4x the "
            "minutes)");
      if (heldOut[0] == '\0' && ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Without a held-out folder each model's fine-tune is repeated with each "
            "of three folds of the training set's sources left out (a fine-tune per "
            "fold) and adopted only where it is better on the left-out objects beyond "
            "their noise, then "
            "fine-tuned on the whole set: four fine-tunes where it is adopted, three "
            "where not. A training set of one source is fine-tuned unguarded");
      ImGui::Checkbox("keep the loaded networks", &keepInit);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Each fine-tuned network joins the loaded model's networks (their "
                          "fields averaged) instead of replacing them, so what they knew stays; "
                          "a network an earlier such fine-tune added is replaced");
    }
    ImGui::BeginDisabled(category.empty());
    const std::string label = category.empty()        ? "Train (set a category)"
                              : initModels.empty() ? "Train " + category + " models"
                                                   : "Fine-tune " + category + " models";
    // What both kinds of training read: the training set, the models in and out, the held-out
    // folder, and the queue to predict again.
    auto request = [&] {
      TrainingRequest r;
      r.dataset = session.trainingSetDir;
      r.outDir = modelsOut;
      r.initDir = initModels;
      r.heldOut = heldOut;
      r.keepInitNetworks = keepInit;
      r.requeue = session.queue().entries();
      return r;
    };
    if (ImGui::Button(label.c_str(), ImVec2(-1, 0))) {
      TrainingRequest models = request();
      models.category = category;
      models.minutesPerModel = minutes;
      worker.start(std::move(models));
    }
    ImGui::EndDisabled();
    // Retraining one of the learned decisions that are not networks: a full-width button that
    // starts the request with `what` switched on, and its tooltip.
    auto retrainButton = [&](const char* label, bool TrainingRequest::*what, const char* tooltip) {
      if (ImGui::Button(label, ImVec2(-1, 0))) {
        TrainingRequest r = request();
        r.*what = true;
        worker.start(std::move(r));
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
    };
    // The categories the curator confirmed or switched train the classifier too.
    retrainButton("Retrain category classifier", &TrainingRequest::categoryClassifier,
                  "Stove / sink / none, learned again from the training set's curated categories "
                  "and the classifier's own training data; kept only where it decides more "
                  "right, beyond the noise of the objects: of the held-out folder when given, else "
                  "of the training set, each "
                  "source left out of training in turn");
    // The points the curator accepted, moved, added or deleted teach the point decision too.
    retrainButton(
        "Retrain point decision", &TrainingRequest::pointScorer,
        "Which of the fields' minima and the mesh's small parts are points, learned "
        "again from the training set's curated points and generated objects (the "
        "bench's val and decision splits, made once); each category's kept only where it needs "
        "fewer edits, beyond the noise of the objects, on its held-out objects, else "
        "on the training set, each source left out of the fitting in turn");
    // The units the curator set or confirmed teach the units guess's memory of real sizes.
    retrainButton("Grow units memory", &TrainingRequest::unitsMemory,
                  "The real sizes of the training set's objects (their curated units) join the "
                  "units guess's memory of curated objects; kept only where, each source left "
                  "out, it guesses units right more often than the named units alone, beyond the "
                  "noise of the objects");
  } else {
    ImGui::ProgressBar(status.fraction, ImVec2(-70, 0));
    ImGui::SameLine();
    if (ImGui::Button("Cancel##train")) worker.cancel();
  }
  if (!status.phase.empty()) ImGui::TextDisabled("%s", status.phase.c_str());
  if (!status.losses.empty()) {
    ImGui::PlotLines("##loss", status.losses.data(), int(status.losses.size()), 0, "loss (L1 on D)",
                     0.0f, FLT_MAX, ImVec2(-1, 70));
  }
  if (!status.finished.empty()) ImGui::TextWrapped("%s", status.finished.c_str());
  for (const auto& verdict : status.verdicts) ImGui::TextWrapped("guard: %s", verdict.c_str());
  if (!status.error.empty())
    ImGui::TextColored(ImVec4(1, 0.45f, 0.45f, 1), "%s", status.error.c_str());
}

}  // namespace sagrid::ui
