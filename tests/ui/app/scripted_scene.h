// Shared by the scripted interaction tests: a tiny OBJ scene (a 1 m plate with a 0.2 m high block
// on it) with labels, a headless App on it viewed from straight above, and helpers that replay
// the input a user would produce, one frame per event batch.
#pragma once

#include <filesystem>
#include <fstream>
#include <chrono>
#include <memory>
#include <thread>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/labels/labels.h"
#include "ui/app/app.h"
#include "ui/gl/gl_context.h"

namespace sagrid::ui::test {

inline void writeSceneObj(const std::filesystem::path& path) {
  std::ofstream obj(path);
  obj << "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\n"
         "f 1 2 3\nf 1 3 4\n";
  // Block x in [0.1, 0.4], y in [-0.4, -0.1], z in [0, 0.2]: its top is at z = 0.2.
  obj << "v 0.1 -0.4 0.2\nv 0.4 -0.4 0.2\nv 0.4 -0.1 0.2\nv 0.1 -0.1 0.2\n"
         "v 0.1 -0.4 0\nv 0.4 -0.4 0\nv 0.4 -0.1 0\nv 0.1 -0.1 0\n"
         "f 5 6 7\nf 5 7 8\nf 9 10 6\nf 9 6 5\nf 10 11 7\nf 10 7 6\nf 11 12 8\nf 11 8 7\nf 12 9 "
         "5\nf 12 5 8\n";
}

inline void writeSceneLabels(const std::filesystem::path& path) {
  ObjectLabels labels;
  labels.object.id = "scene";
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  AffordancePoint heat;
  heat.type = "heatsource";
  heat.position = {-0.2f, 0.2f, 0.0f};
  AffordancePoint toggle;
  toggle.type = "togglebutton";
  toggle.position = {-0.3f, -0.3f, 0.0f};
  labels.affordances = {heat, toggle};
  writeLabels(path, labels);
}

class ScriptedApp {
 public:
  // `modelsDir`: the models "Run SAGrid" predicts with (none by default: tests script predictions).
  explicit ScriptedApp(const std::filesystem::path& dir, int width = 480, int height = 400,
                       const std::filesystem::path& modelsDir = {}) {
    writeSceneObj(dir / "mesh.obj");
    writeSceneLabels(dir / "labels.json");
    ContextOptions options;
    options.width = width;
    options.height = height;
    context = createGlContext(GlBackend::Egl, options);
    AppOptions appOptions;
    appOptions.autoPredict = false;
    appOptions.modelsDir = modelsDir;
    appOptions.trainingSet = dir / "training";
    appOptions.screenshotDir = dir;
    app = std::make_unique<App>(*context, appOptions);
    app->session().view().showPanels = false;  // the whole window is viewport
    app->session().openObject(dir / "mesh.obj", dir / "labels.json");
    app->frame({});
    // Straight down onto the plate, so window pixels map simply onto the plane.
    app->session().camera().set({0, 0, 0}, 2.5f, -1.5707963f, 1.5f);
    app->frame({});
  }

  // The window pixel where a z-up world point is drawn.
  Eigen::Vector2f pixelOf(const Eigen::Vector3f& world) const {
    Eigen::Vector2f p;
    app->session().camera().project(world, p);
    const ViewportRect& vp = app->session().viewport();
    return p + Eigen::Vector2f(vp.x, vp.y);
  }

  void frame(std::vector<InputEvent> events) { app->frame(events); }
  void moveTo(const Eigen::Vector2f& p) { frame({InputEvent::mouseMove(p.x(), p.y())}); }
  void press(int mods = 0) { frame({InputEvent::mouseButton(GLFW_MOUSE_BUTTON_LEFT, true, mods)}); }
  void release(int mods = 0) {
    frame({InputEvent::mouseButton(GLFW_MOUSE_BUTTON_LEFT, false, mods)});
  }
  void click(const Eigen::Vector2f& p, int mods = 0) {
    moveTo(p);
    press(mods);
    release(mods);
  }
  void drag(const Eigen::Vector2f& from, const Eigen::Vector2f& to, int steps = 6) {
    moveTo(from);
    press();
    for (int s = 1; s <= steps; ++s) moveTo(from + (to - from) * (float(s) / float(steps)));
    release();
  }
  void key(int glfwKey, int mods = 0) {
    frame({InputEvent::keyEvent(glfwKey, true, mods)});
    frame({InputEvent::keyEvent(glfwKey, false, mods)});
  }

  // Runs a prediction that returns `result` through the session's real worker and waits for it.
  void predict(PredictionResult result) {
    Session& session = app->session();
    session.setPredictorLookup([result](const AnnotationDocument&) -> std::optional<PredictionJob> {
      return PredictionJob([result](PredictionProgress& progress) {
        progress.fraction = 1.0f;
        return result;
      });
    });
    session.runPrediction();
    for (int i = 0; i < 200 && session.worker().running(); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      frame({});
    }
    frame({});
  }

  const AnnotationDocument& document() const { return *app->session().document(); }

  std::unique_ptr<GlContext> context;
  std::unique_ptr<App> app;
};

}  // namespace sagrid::ui::test
