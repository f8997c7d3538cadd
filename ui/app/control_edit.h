// The curator's reshaping of a toggle button's control part (issue 42): the Points panel's Grow
// and Shrink and the viewport's part brush. Each change is one undoable SetControlCommand whose
// part is the curator's ("marked"), its motion, axis and pivot found again from the new shape; the
// burner it drives stays.
#pragma once

#include <string>
#include <vector>

namespace sagrid {
struct SurfaceHit;
}

namespace sagrid::ui {

class Session;

// The brush of the viewport: while armed, a click on the surface adds the connected surface
// within the radius to the selected toggle button's part, Ctrl+click takes it away
// (core/controls/control_part_edit.h: brushedPart).
struct PartBrush {
  bool armed = false;
  float radiusCm = 1.5f;
};

// Gives point `index` (a toggle button) the part of `triangles` (mesh indices); nothing when they
// are empty or the part's already. Returns whether a command ran.
bool reshapeControlPart(Session& session, int index, std::vector<int> triangles,
                        const std::string& what);

// The brush at `hit` (on the open document's surface) on the selected point's part. False when
// no toggle button is selected or nothing changed.
bool brushControlPart(Session& session, const SurfaceHit& hit, bool remove);

}  // namespace sagrid::ui
