#include "ui/app/app.h"

#include <imgui.h>

#include "core/common/error.h"
#include "core/common/log.h"
#include "ui/app/shortcuts.h"
#include "ui/gl/framebuffer.h"
#include "ui/gl/gl.h"

namespace sagrid::ui {

App::App(GlContext& context, AppOptions options)
    : m_context(context),
      m_options(std::move(options)),
      m_session(m_options.recentFiles),
      m_imgui(context),
      m_predictor(m_options.modelsDir) {
  if (m_options.trainedModelsDir.empty())
    m_options.trainedModelsDir = m_options.trainingSet / "models";
  m_session.categoryReadsFileName = m_options.readFileName;
  if (!m_options.modelsDir.empty()) m_session.setPredictorLookup(predictorLookup());
  m_session.autoPredict = m_options.autoPredict;
  m_session.trainingSetDir = m_options.trainingSet;
  int w = 0, h = 0;
  m_context.windowSize(w, h);
  m_session.setViewport({0, 0, float(w), float(h)});
}

App::~App() = default;

PredictorLookup App::predictorLookup() {
  return [this](const AnnotationDocument& doc) {
    m_predictor.setReadFileName(m_session.categoryReadsFileName);
    return m_predictor.jobFor(doc);
  };
}

void App::frame(const std::vector<InputEvent>& events, double deltaSeconds) {
  m_imgui.beginFrame(events, deltaSeconds);
  try {
    for (const InputEvent& e : events) {
      if (e.kind != InputEvent::Kind::Drop) continue;
      std::vector<std::filesystem::path> paths(e.paths.begin(), e.paths.end());
      m_session.addPaths(paths);
    }
    m_input.handle(events, m_session, m_imgui.wantsMouse());
    if (handleShortcuts(events, m_session, m_imgui.wantsKeyboard())) m_quit = true;
    m_session.pollPrediction();
    if (m_training.takeFinished()) {
      // The new models predict from now on; the open object shows its new prediction if unreviewed.
      m_predictor.setModelsDir(m_options.trainedModelsDir);
      m_session.setPredictorLookup(predictorLookup());
      const auto& queue = m_session.queue();
      if (!queue.empty() &&
          queue.entry(std::size_t(queue.current())).state == QueueState::Unreviewed) {
        m_session.openEntry(queue.current());
      }
    }
  } catch (const Error& e) {
    // The frame boundary: whatever core threw is shown, and the session goes on.
    m_session.reportError(e.what());
  }

  if (drawMainMenu(m_session, m_browser)) m_quit = true;
  layoutPanels();
  drawViewportOverlay(m_session, m_scene);
  m_browser.draw(m_session);
  drawHelpOverlay(m_session);
  drawErrorModal(m_session);

  try {
    m_scene.sync(m_session.document(), m_input.dragPreview(), m_session.view());
  } catch (const Error& e) {
    m_session.reportError(e.what());
  }
  drawScene();
  m_imgui.render();

  if (m_session.screenshotRequested) {
    m_session.screenshotRequested = false;
    // The next number no file in the folder has: a screenshot of an earlier session stays.
    std::filesystem::path path;
    std::error_code ec;
    do {
      path = m_options.screenshotDir /
             ("sagrid-screenshot-" + std::to_string(++m_screenshotCount) + ".png");
    } while (std::filesystem::exists(path, ec));
    try {
      writePng(path, capture());
      logger()->info("screenshot saved to {}", path.string());
    } catch (const Error& e) {
      m_session.reportError(e.what());
    }
  }
  if (m_context.shouldClose()) m_quit = true;
}

void App::layoutPanels() {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float top = ImGui::GetFrameHeight();         // main menu bar
  const float bottom = ImGui::GetFrameHeight() + 6;  // status bar
  drawStatusBar(m_session);
  ViewportRect viewport{0, top, display.x, display.y - top - bottom};
  if (m_session.view().showPanels) {
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::SetNextWindowPos(ImVec2(0, top));
    ImGui::SetNextWindowSize(ImVec2(m_layout.leftWidth, viewport.height));
    ImGui::Begin("##left", nullptr, flags);
    drawQueuePanel(m_session, m_predictor.confidence());
    drawPointsPanel(m_session);
    ImGui::End();
    ImGui::SetNextWindowPos(ImVec2(display.x - m_layout.rightWidth, top));
    ImGui::SetNextWindowSize(ImVec2(m_layout.rightWidth, viewport.height));
    ImGui::Begin("##right", nullptr, flags);
    drawObjectPanel(m_session);
    drawFieldPanel(m_session, m_scene);
    drawTrainPanel(m_session, m_training, m_options.trainedModelsDir, m_predictor.modelsDir());
    drawLogPanel(m_log.buffer());
    ImGui::End();
    viewport.x = m_layout.leftWidth;
    viewport.width = std::max(1.0f, display.x - m_layout.leftWidth - m_layout.rightWidth);
  }
  const bool sizeChanged = viewport.width != m_session.viewport().width ||
                           viewport.height != m_session.viewport().height;
  m_session.setViewport(viewport);
  if (sizeChanged && m_session.document() && !m_session.document()->canUndo()) {
    // Keep the object framed while the layout settles (first frames, window resizes).
    m_session.frameObject();
  }
}

void App::drawScene() {
  int fbWidth = 0, fbHeight = 0, winWidth = 0, winHeight = 0;
  m_context.framebufferSize(fbWidth, fbHeight);
  m_context.windowSize(winWidth, winHeight);
  const float scale = winWidth > 0 ? float(fbWidth) / float(winWidth) : 1.0f;
  glBindFramebuffer(GL_FRAMEBUFFER, m_context.screenFramebuffer());
  glViewport(0, 0, fbWidth, fbHeight);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.155f, 0.165f, 0.19f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const ViewportRect& vp = m_session.viewport();
  const int x = int(vp.x * scale), w = int(vp.width * scale), h = int(vp.height * scale);
  const int y = fbHeight - int((vp.y + vp.height) * scale);  // GL's origin is bottom-left
  glViewport(x, y, w, h);
  m_scene.draw(m_session.camera(), m_session.view());
  glViewport(0, 0, fbWidth, fbHeight);
}

RgbaImage App::capture() const {
  int w = 0, h = 0;
  m_context.framebufferSize(w, h);
  return readFramebuffer(m_context.screenFramebuffer(), w, h);
}

void App::run() {
  std::vector<InputEvent> events;
  double last = m_context.timeSeconds();
  while (!m_quit) {
    events.clear();
    // Sleep until input arrives, but keep animating while a prediction runs.
    // A panel click's release held back for the next frame is drawn at once.
    m_context.waitEvents(m_imgui.hasPendingInput() ? 0.0 : m_session.worker().running() ? 0.05 : 0.25);
    m_context.pollEvents(events);
    const double now = m_context.timeSeconds();
    frame(events, now - last);
    last = now;
    m_context.present();
  }
}

}  // namespace sagrid::ui
