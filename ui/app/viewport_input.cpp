#include "ui/app/viewport_input.h"

#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/geometry/surface_scene.h"
#include "ui/app/control_edit.h"
#include "ui/app/session.h"
#include "ui/document/point_commands.h"

namespace sagrid::ui {

namespace {
constexpr float kClickSlop = 3.0f;        // pixels a click may wander before it is a drag
constexpr float kPickRadius = 14.0f;      // pixels around a marker centre
constexpr float kOrbitPerPixel = 0.008f;  // radians

std::optional<SurfaceHit> surfaceUnder(const Session& session, float x, float y) {
  const AnnotationDocument* doc = session.document();
  if (!doc) return std::nullopt;
  const ViewportRect& vp = session.viewport();
  const Ray ray = session.camera().rayThrough(x - vp.x, y - vp.y);
  return doc->surface().intersect(ray.origin, ray.direction);
}
}  // namespace

int ViewportInput::pickMarker(const Session& session, float x, float y, float radius) {
  const AnnotationDocument* doc = session.document();
  if (!doc || !session.view().showPoints) return -1;
  const ViewportRect& vp = session.viewport();
  int best = -1;
  float bestDistance = radius;
  for (int i = 0; i < static_cast<int>(doc->points().size()); ++i) {
    Eigen::Vector2f pixel;
    if (!session.camera().project(doc->pointInView(i), pixel)) continue;
    const float d = (pixel + Eigen::Vector2f(vp.x, vp.y) - Eigen::Vector2f(x, y)).norm();
    if (d <= bestDistance) best = i, bestDistance = d;
  }
  return best;
}

void ViewportInput::handle(const std::vector<InputEvent>& events, Session& session,
                           bool panelsWantMouse) {
  for (const InputEvent& e : events) {
    switch (e.kind) {
      case InputEvent::Kind::MouseMove:
        move(e.x, e.y, session);
        break;
      case InputEvent::Kind::MouseButton:
        if (e.pressed && m_gesture == Gesture::None && !panelsWantMouse &&
            session.viewport().contains(m_x, m_y)) {
          press(e, session);
        } else if (!e.pressed && e.button == m_button) {
          release(e, session);
        }
        break;
      case InputEvent::Kind::Scroll:
        if (!panelsWantMouse && session.viewport().contains(m_x, m_y)) {
          if (const auto hit = surfaceUnder(session, m_x, m_y))
            session.camera().zoomTowards(e.y, hit->position);
          else
            session.camera().zoom(e.y);
          session.noteLook("zoom");
        }
        break;
      default:
        break;
    }
  }
}

void ViewportInput::press(const InputEvent& e, Session& session) {
  m_button = e.button;
  m_mods = e.mods;
  m_pressX = m_x, m_pressY = m_y;
  m_moved = false;
  if (e.button == GLFW_MOUSE_BUTTON_LEFT) {
    int marker = (e.mods & GLFW_MOD_SHIFT) || session.addModeArmed
                     ? -1
                     : pickMarker(session, m_x, m_y, kPickRadius);
    // With the brush on, the selected point's own marker sits on the part being brushed: a click
    // there brushes the surface under it instead of grabbing the point.
    if (session.partBrush.armed && marker >= 0 && marker == session.document()->selected() &&
        brushApplies(session))
      marker = -1;
    if (marker >= 0) {
      session.document()->select(marker);
      m_gesture = Gesture::PointDrag;
      m_dragIndex = marker;
    } else {
      m_gesture = Gesture::Click;  // becomes Orbit once it moves
    }
  } else {
    m_gesture = Gesture::Pan;
  }
}

void ViewportInput::move(float x, float y, Session& session) {
  const float dx = x - m_x, dy = y - m_y;
  m_x = x, m_y = y;
  if (m_gesture == Gesture::None) return;
  if (std::hypot(x - m_pressX, y - m_pressY) > kClickSlop) m_moved = true;
  switch (m_gesture) {
    case Gesture::Click:
      if (m_moved) m_gesture = Gesture::Orbit;
      [[fallthrough]];
    case Gesture::Orbit:
      if (m_gesture == Gesture::Orbit)
        session.camera().orbit(-dx * kOrbitPerPixel, dy * kOrbitPerPixel);
      break;
    case Gesture::Pan:
      session.camera().pan(dx, dy);
      break;
    case Gesture::PointDrag:
      if (m_moved) {
        // Snap to the surface under the pointer; off the mesh, the point stays where it was last.
        if (auto hit = surfaceUnder(session, x, y)) {
          m_drag = DragPreview{m_dragIndex, hit->position};
          m_dragNormal = hit->normal;
        }
      }
      break;
    case Gesture::None:
      break;
  }
}

void ViewportInput::release(const InputEvent&, Session& session) {
  AnnotationDocument* doc = session.document();
  if (m_gesture == Gesture::PointDrag && m_drag && doc) {
    const Eigen::Vector3f normalFile = doc->toFile(*m_dragNormal);
    session.execute(std::make_unique<MovePointCommand>(m_drag->index, doc->toFile(m_drag->position),
                                                       normalFile.normalized()));
  } else if (m_gesture == Gesture::Click && doc) {
    const bool add = (m_mods & GLFW_MOD_SHIFT) || session.addModeArmed;
    if (session.partBrush.armed && !add && brushApplies(session)) {
      // The brush keeps the selection: a click on the surface reshapes the selected part.
      if (auto hit = surfaceUnder(session, m_x, m_y))
        brushControlPart(session, *hit,
                         (m_mods & GLFW_MOD_CONTROL) ? BrushMode::Away
                         : (m_mods & GLFW_MOD_ALT)   ? BrushMode::Replace
                                                     : BrushMode::Add);
    } else if (add) {
      if (auto hit = surfaceUnder(session, m_x, m_y)) {
        AffordancePoint point;
        point.type = session.currentType();
        point.position = doc->toFile(hit->position);
        point.normal = doc->toFile(hit->normal).normalized();
        session.execute(std::make_unique<AddPointCommand>(std::move(point)));
        session.addModeArmed = false;
      }
    } else {
      doc->select(pickMarker(session, m_x, m_y, kPickRadius));
    }
  }
  if (m_gesture == Gesture::Orbit || (m_gesture == Gesture::Pan && m_moved)) {
    session.noteLook(m_gesture == Gesture::Orbit ? "orbit" : "pan");
  }
  m_gesture = Gesture::None;
  m_button = -1;
  m_drag.reset();
  m_dragNormal.reset();
  m_dragIndex = -1;
}

}  // namespace sagrid::ui
