// The ImGui panels of the annotation GUI. Each panel only reads the Session and calls its actions
// (which turn point edits into document commands); none keeps state of the document itself.
#pragma once

#include <filesystem>

#include "ui/app/log_buffer.h"

namespace sagrid {
struct ConfidenceCalibration;
}

namespace sagrid::ui {

class Session;
class SceneRenderer;
class FileBrowser;
class TrainingWorker;

struct PanelLayout {
  float menuHeight = 0;
  float leftWidth = 310;
  float rightWidth = 300;
};

// Returns true when the user chose File -> Quit.
bool drawMainMenu(Session& session, FileBrowser& browser);
// `confidence`: the models' confidence map, for the precision measured at the auto-accept setting.
void drawQueuePanel(Session& session, const ConfidenceCalibration& confidence);
void drawPointsPanel(Session& session);
// The selected toggle button's control part, motion, axis and burner (inside the Points panel).
void drawControlEditor(Session& session, int index);
void drawFieldPanel(Session& session, const SceneRenderer& scene);
void drawObjectPanel(Session& session);
void drawLogPanel(const LogBuffer& log);
// Retrain the open object's category on the training set, live loss curve, then re-predict.
// `initModels`: the models the GUI uses, fine-tuned (with the bench replay) instead of trained
// from scratch; empty = from scratch.
void drawTrainPanel(Session& session, TrainingWorker& worker,
                    const std::filesystem::path& modelsOut,
                    const std::filesystem::path& initModels = {});
void drawHelpOverlay(Session& session);
void drawErrorModal(Session& session);
// Labels next to the markers, the axes gizmo and the colour legend, over the 3D viewport.
void drawViewportOverlay(const Session& session, const SceneRenderer& scene);
// Status line: prediction progress and cancel, add mode, k/n.
void drawStatusBar(Session& session);

}  // namespace sagrid::ui
