#include "ui/app/headless_render.h"

#include <chrono>
#include <cmath>
#include <thread>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/labels/labels.h"
#include "ui/app/app.h"
#include "ui/document/review_queue.h"

namespace sagrid::ui {
namespace fs = std::filesystem;

void parseSize(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  try {
    if (x == std::string::npos) throw std::invalid_argument(text);
    width = std::stoi(text.substr(0, x));
    height = std::stoi(text.substr(x + 1));
  } catch (const std::exception&) {
    throw InvalidArgument("--size '" + text + "' is not WIDTHxHEIGHT, e.g. 640x480");
  }
  if (width < 16 || height < 16 || width > 8192 || height > 8192) {
    throw InvalidArgument("--size '" + text + "' is out of range (16..8192 per side)");
  }
}

void renderScreenshot(const RenderOptions& options) {
  // Bad input is answered before a GL context is made (that takes seconds).
  const fs::path labelsPath = options.labels.empty() ? labelsPathFor(options.mesh) : fs::path(options.labels);
  requireRegularFile(options.mesh);
  std::error_code ec;
  if (!options.labels.empty() || fs::exists(labelsPath, ec)) readLabels(labelsPath);
  ContextOptions contextOptions;
  contextOptions.width = options.width;
  contextOptions.height = options.height;
  contextOptions.visible = false;
  auto context = createGlContext(options.backend, contextOptions);
  AppOptions appOptions;
  appOptions.autoPredict = false;
  appOptions.modelsDir = options.modelsDir;
  App app(*context, appOptions);
  Session& session = app.session();
  session.readOnly = true;  // a render never changes the object's labels.json
  session.logErrors = false;  // thrown below; main prints it once
  session.openObject(options.mesh, labelsPath);
  if (!session.pendingErrors().empty()) throw Error(session.pendingErrors().front());
  if (!options.modelsDir.empty()) {
    session.runPrediction();
    while (session.worker().running()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    app.frame({});  // applies the prediction
    if (!session.pendingErrors().empty()) throw Error(session.pendingErrors().front());
  }
  ViewSettings& view = session.view();
  view.field.visible = options.showField;
  view.showPanels = options.showPanels;
  view.wireframe = options.wireframe;
  view.controlTurn = options.controlTurn;
  view.surface = options.surface;
  // Two frames let ImGui settle its window sizes (auto-fit happens on the second frame).
  app.frame({});
  app.frame({});
  if (!options.fieldType.empty()) {
    const auto& types = app.scene().field().types();
    std::uint32_t mask = 0;
    for (std::size_t i = 0; i < types.size(); ++i) {
      if (types[i] == options.fieldType) mask |= 1u << i;
    }
    if (!mask)
      throw InvalidArgument("--field-type " + options.fieldType +
                            ": the object has no field of that type");
    view.field.typeMask = mask;
  }
  if (options.closeUpPoint) {
    const int count = static_cast<int>(session.document()->points().size());
    if (*options.closeUpPoint < 1 || *options.closeUpPoint > count)
      throw InvalidArgument("--close-up " + std::to_string(*options.closeUpPoint) + ": the object has " +
                            std::to_string(count) + " points (numbered from 1)");
    session.document()->select(*options.closeUpPoint - 1);
    session.frameSelection();
  }
  if (options.yawDegrees || options.pitchDegrees) {
    Camera& camera = session.camera();
    const float yaw =
        options.yawDegrees ? *options.yawDegrees * float(M_PI) / 180.0f : camera.yaw();
    const float pitch =
        options.pitchDegrees ? *options.pitchDegrees * float(M_PI) / 180.0f : camera.pitch();
    camera.set(camera.target(), camera.distance(), yaw, pitch);
  }
  app.frame({});
  writePng(options.screenshot, app.capture());
}

}  // namespace sagrid::ui
