// `sagrid render`: opens one object in the GUI's frame function on a GL context (EGL headless by
// default) and saves the frame as a PNG — the same pixels the window would show.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "ui/gl/gl_context.h"
#include "ui/render/view_settings.h"

namespace sagrid::ui {

struct RenderOptions {
  std::filesystem::path mesh;
  std::filesystem::path labels;      // empty = labels.json beside the mesh (if any)
  std::filesystem::path screenshot;  // PNG to write
  GlBackend backend = GlBackend::Egl;
  int width = 1280, height = 800;
  bool showField = false;
  std::filesystem::path modelsDir;  // run SAGrid with these models first (empty = no prediction)
  std::string fieldType;            // show only this type's field (empty = all)
  bool showPanels = true;
  bool wireframe = false;
  std::optional<float> yawDegrees, pitchDegrees;
  // Frame point N (1-based, as the Points panel numbers them) in a close-up, as F does in the GUI.
  std::optional<int> closeUpPoint;
  // Every toggle button's control moved as the exports move it, knobs and levers by this many
  // radians (View > Controls turned in the GUI); 0: as modelled.
  float controlTurn = 0.0f;
  SurfaceColouring surface = SurfaceColouring::Modelled;  // View > Plain grey / by material / texture contrast
};

// Throws sagrid::Error when the context, the mesh or the output cannot be used.
void renderScreenshot(const RenderOptions& options);

// Parses "WIDTHxHEIGHT"; throws InvalidArgument.
void parseSize(const std::string& text, int& width, int& height);

}  // namespace sagrid::ui
