// What the viewport shows and how: toggles and slider values the panels edit and the renderers
// read. Plain data, no GL, so the same settings drive the window, `sagrid render` and tests.
#pragma once

#include <cstdint>

namespace sagrid::ui {

struct FieldSettings {
  bool visible = true;
  float threshold = 0.0f;  // show voxels closer than this (mesh units); 0 = not yet set
  float colorMax = 0.0f;   // distance mapped to the far end of the colour map; 0 = auto
  float opacity = 1.0f;
  int sliceAxis = -1;            // -1 none, 0/1/2 = x/y/z
  float slice = 1.0f;            // slice plane position as a fraction of the object's extent
  std::uint32_t typeMask = ~0u;  // bit per field index
};

// The angle View > Controls turned (T) shows: RoboCasa lights a burner from 0.35 rad; the
// exports' tests turn 0.6.
inline constexpr float kPreviewTurn = 0.6f;

// How the mesh's surface is coloured: one view at a time (G, M and B each toggle theirs).
enum class SurfaceColouring {
  Modelled,    // materials, textures and vertex colours, lit
  // One light grey, without textures, materials or vertex colours: the shape of a model whose
  // materials are black (its wireframe shows on it too).
  PlainGrey,
  // Each material in a colour of its own, without textures or vertex colours: parts that differ
  // from their surroundings only by material (touch keys of their own material on a black glass
  // top, a knob of another plastic) stand out; marks only in a texture do not.
  ByMaterial,
  // Each texture nearly unlit with its own luminance range stretched (texture_contrast.h): marks
  // printed faintly in a texture (a ceramic hob's touch keys) stand out.
  TextureContrast,
};

// `colouring`, or back to as modelled where it is the one shown (what its key or menu item does).
inline void toggleSurfaceColouring(SurfaceColouring& shown, SurfaceColouring colouring) {
  shown = shown == colouring ? SurfaceColouring::Modelled : colouring;
}

struct ViewSettings {
  bool showMesh = true;
  bool wireframe = false;
  SurfaceColouring surface = SurfaceColouring::Modelled;
  bool showGrid = true;
  bool showAxes = true;
  bool showPoints = true;
  bool showPointLabels = true;
  bool showPanels = true;
  float markerPixels = 9.0f;  // marker radius on screen
  // The mesh drawn with every toggle button's control moved as the exports move it (knobs and
  // levers turned by this many radians, buttons pressed); 0: as modelled.
  float controlTurn = 0.0f;
  FieldSettings field;
};

}  // namespace sagrid::ui
