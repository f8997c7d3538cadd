// Mouse and keyboard in the 3D viewport: orbit (left drag on empty space), pan (right or middle
// drag, or Shift+arrows), zoom (wheel, +/-), click a marker to select it, drag a marker along the
// mesh surface (a ray cast every frame snaps it to the surface; the release becomes one
// MovePointCommand), add a point by Shift+click on the surface or a click while "add" is armed,
// brush the selected control's part by a click while the brush is armed (Ctrl: away, Alt: anew;
// a click on the selected point's own marker brushes the surface under it).
#pragma once

#include <optional>
#include <vector>

#include "ui/gl/input_event.h"
#include "ui/render/scene_renderer.h"

namespace sagrid::ui {

class Session;

class ViewportInput {
 public:
  // `panelsWantMouse`: the pointer is over an ImGui panel (events then go to the panel, except
  // the end of a drag that began in the viewport).
  void handle(const std::vector<InputEvent>& events, Session& session, bool panelsWantMouse);
  const std::optional<DragPreview>& dragPreview() const { return m_drag; }
  // Index of the marker under window pixel (x, y) within `radius` pixels, or -1.
  static int pickMarker(const Session& session, float x, float y, float radius);

 private:
  enum class Gesture { None, Orbit, Pan, PointDrag, Click };
  void press(const InputEvent& e, Session& session);
  void release(const InputEvent& e, Session& session);
  void move(float x, float y, Session& session);

  Gesture m_gesture = Gesture::None;
  int m_button = -1;
  int m_mods = 0;
  float m_x = 0, m_y = 0;  // last pointer position (window)
  float m_pressX = 0, m_pressY = 0;
  bool m_moved = false;
  int m_dragIndex = -1;
  std::optional<DragPreview> m_drag;
  std::optional<Eigen::Vector3f> m_dragNormal;
};

}  // namespace sagrid::ui
