// The annotation GUI application: one frame function (input -> panels -> scene -> ImGui) shared
// by the window loop, the headless `sagrid render`, benchmarks and scripted interaction tests,
// so the headless image is exactly what the window shows.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "ui/app/imgui_layer.h"
#include "ui/app/log_buffer.h"
#include "ui/app/model_predictor.h"
#include "ui/app/session.h"
#include "ui/app/training_worker.h"
#include "ui/app/viewport_input.h"
#include "ui/gl/gl_context.h"
#include "ui/gl/image.h"
#include "ui/panels/file_browser.h"
#include "ui/panels/panels.h"
#include "ui/render/scene_renderer.h"

namespace sagrid::ui {

struct AppOptions {
  std::filesystem::path recentFiles;  // empty = in memory (tests)
  std::filesystem::path trainingSet = "training-set";
  bool autoPredict = true;
  std::filesystem::path screenshotDir = ".";  // F12 screenshots
  std::filesystem::path modelsDir;            // model cards for "Run SAGrid"; empty = none
  // Where the Train panel writes models (then used for predictions); empty = trainingSet/models.
  std::filesystem::path trainedModelsDir;
  // The category classifier reads the words of the mesh file's name (`--no-file-name`: not).
  bool readFileName = true;
};

class App {
 public:
  App(GlContext& context, AppOptions options);
  ~App();

  // Draws one frame into the context's screen framebuffer from the input of this frame.
  void frame(const std::vector<InputEvent>& events, double deltaSeconds = 1.0 / 60.0);
  // The window loop: polls input, draws, presents; returns when the window closes.
  void run();
  // The last frame's pixels.
  RgbaImage capture() const;

  Session& session() { return m_session; }
  const SceneRenderer& scene() const { return m_scene; }
  const ViewportInput& viewportInput() const { return m_input; }
  bool quitRequested() const { return m_quit; }

 private:
  void layoutPanels();
  // The session's predictions by the models folder, reading the file's name as the session says.
  PredictorLookup predictorLookup();
  void drawScene();

  GlContext& m_context;
  AppOptions m_options;
  ScopedLogPanelSink m_log;
  Session m_session;
  ImGuiLayer m_imgui;
  SceneRenderer m_scene;
  ViewportInput m_input;
  FileBrowser m_browser;
  PanelLayout m_layout;
  ModelPredictor m_predictor;
  TrainingWorker m_training;
  bool m_quit = false;
  int m_screenshotCount = 0;
};

}  // namespace sagrid::ui
